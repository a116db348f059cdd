// Writes a run's report files into a folder: report.json, map.png, weights.png.
#pragma once

#include <string>

#include "lib/report/run_record.hpp"
#include "lib/report/run_scoring.hpp"

namespace beft::report {

// Creates out_dir if needed. Throws ReportError naming the file that could
// not be written.
void writeReportFiles(const RunRecord& record, const RunReport& report, const std::string& out_dir);

}  // namespace beft::report

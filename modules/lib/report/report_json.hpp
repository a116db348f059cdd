// The run report as JSON (report.json) and as a short text for a person.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "lib/report/run_scoring.hpp"

namespace beft::report {

nlohmann::json toJson(const RunReport& report);
void printSummary(const RunReport& report, std::ostream& out);

}  // namespace beft::report

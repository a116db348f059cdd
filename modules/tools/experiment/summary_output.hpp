// The summary written as summary.csv (one row per condition, then one per
// comparison), summary.json, and printed as a table.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>

#include "tools/experiment/summary.hpp"

namespace beft::experiment {

void writeSummaryCsv(const Summary& summary, std::ostream& out);
nlohmann::json summaryJson(const Summary& summary);
void printSummary(const Summary& summary, std::ostream& out);

}  // namespace beft::experiment

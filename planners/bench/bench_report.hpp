// The benchmark's outputs: a printed table, CSV files and a plot of length
// ratio against planning time per planner (drawn with OpenCV).
#pragma once

#include "planners/bench/bench_stats.hpp"

#include <opencv2/core.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace beft::planners::bench {

void printTable(std::ostream& out, const std::vector<Summary>& rows);

// One line per run / per summary row; throws std::runtime_error naming the
// file when it cannot be written.
void writeRunsCsv(const std::string& file, const std::vector<RunRecord>& runs);
void writeSummaryCsv(const std::string& file, const std::vector<Summary>& rows);

// Successful runs as dots (x: planning time, log scale; y: length / octile
// optimum), each planner's median as a large marker, a legend with success
// rates. Planners in `planners` order.
cv::Mat plotLengthRatioVsTime(const std::vector<RunRecord>& runs, const std::vector<std::string>& planners,
                              const std::string& title);

// Quotes a CSV field when needed.
std::string csvField(const std::string& text);

}  // namespace beft::planners::bench

// The run's record of firings: one readable line each on a stream, and
// optionally a CSV file (one row per attempt) for analysis.
#pragma once

#include <cstdio>
#include <fstream>
#include <string>

#include "arbiter_core.hpp"

namespace beft::arbiter {

// "tick     3  firing    31  vision            ok       0.41 ms  (expert 0.30 ms)"
std::string formatFiringLine(const FiringRecord& record);

// The CSV header and one row; the message is quoted when it needs to be.
std::string firingCsvHeader();
std::string formatFiringCsvRow(const FiringRecord& record);

class FiringLog {
 public:
  // lines: where readable lines go (nullptr: none). csv_path: "" for no CSV.
  // Throws std::runtime_error when the CSV file cannot be written.
  FiringLog(std::FILE* lines, const std::string& csv_path);
  void write(const FiringRecord& record);
  void flush();

 private:
  std::FILE* lines_;
  std::ofstream csv_;
};

}  // namespace beft::arbiter

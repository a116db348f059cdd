// The run's record of firings: one readable line each on a stream, and
// optionally a CSV file (one row per attempt) for analysis.
#pragma once

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

#include "services/arbiter/arbiter_core.hpp"

namespace beft::arbiter {

// "tick     3  firing    31  vision            ok       0.41 ms  (expert 0.30 ms)"
std::string formatFiringLine(const FiringRecord& record);

// The CSV header and one row; the message is quoted when it needs to be.
std::string firingCsvHeader();
std::string formatFiringCsvRow(const FiringRecord& record);

class FiringLog {
 public:
  // lines: where readable lines go (nullptr: none). csv_path: "" for no CSV.
  // Lines reach lines at the latest flush_period_s after they were written
  // (and at flush()): a write per firing would cost the lockstep loop a
  // system call and wake whoever reads the output ten times a tick.
  // Throws std::runtime_error when the CSV file cannot be written.
  FiringLog(std::FILE* lines, const std::string& csv_path, double flush_period_s = 0.25);
  void write(const FiringRecord& record);
  void flush();

 private:
  std::FILE* lines_;
  std::ofstream csv_;
  std::chrono::steady_clock::duration flush_period_;
  std::chrono::steady_clock::time_point last_flush_;
};

}  // namespace beft::arbiter

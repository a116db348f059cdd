// The yard rows of beft-bench-view: runs without and with the viewer in
// turns, each printed as it ends, then the means and their ratio.
#pragma once

#include <filesystem>
#include <string>

namespace beft::bench {

struct ViewOptions {
  int ticks = 1000, repeat = 5;  // the yard mission ends at tick 928
  double hold_s = 6;             // every run held this long at its start (yard_runs.hpp)
  long long seed = 1;
  double seconds = 20;  // district_large's page reading
  std::string work = (std::filesystem::temp_directory_path() / "beft_bench_view").string();
};

// The share of its speed the viewed loop must keep.
constexpr double kTargetShare = 0.90;

// Runs and prints the rows; with `viewer` false only the runs without one.
void runSpeedRows(const ViewOptions& o, bool viewer);

// A free TCP port on 127.0.0.1 for a viewer.
int freeTcpPort();

}  // namespace beft::bench

// One benchmark run and the figures summarised over runs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace beft::planners::bench {

struct RunRecord {
  std::string planner;
  std::string dataset;
  std::string map;
  std::string query;        // label of the query on its map
  int map_width = 0, map_height = 0;
  uint64_t seed = 0;
  bool success = false;
  double time_ms = 0;       // solve + tightening [ms]
  double setup_ms = 0;      // per-map preparation of this planner [ms]
  double length = 0;        // [cells]
  double optimum = 0;       // octile optimum [cells]
  double ratio = 0;         // length / optimum
  double turning_deg = 0;   // total heading change along the path [deg] (smoothness)
  double clearance = 0;     // smallest distance to a raw obstacle [cells]
  int waypoints = 0;
  std::string message;
};

struct Summary {
  std::string planner;
  std::string map;          // "all" when summarised over every map
  int runs = 0;
  int successes = 0;
  double success_rate = 0;
  double ratio_median = 0;      // of successful runs (NaN if none)
  double ratio_mean = 0;
  double time_median = 0;       // of all runs [ms]
  double time_p25 = 0, time_p75 = 0;
  double turning_median = 0;    // [deg]
  double clearance_median = 0;  // [cells]
};

// Linear interpolation between order statistics; q in [0, 1]. NaN when empty.
double percentile(std::vector<double> values, double q);
double median(std::vector<double> values);
double mean(const std::vector<double>& values);

// Per (planner, map) in first-seen order, or per planner over all maps.
std::vector<Summary> summarize(const std::vector<RunRecord>& runs, bool per_map);

}  // namespace beft::planners::bench

// The paper's Fig. 3: its particle potential-field planner, as printed
// (pf-paper: the robot traces the winning particle's path h_W), planning
// from three initial positions to one goal in one scene; each path drawn as
// its waypoints with the intended orientation at each, the particles behind.
#pragma once

#include <string>
#include <vector>

#include "planners/geometry.hpp"

namespace beft::figure {

struct Figure3Options {
  std::string scenario_path;                // the scene: its ground-truth obstacles
  std::vector<planners::Point2> starts;     // [m]; three in the paper
  planners::Point2 goal;                    // [m]
  uint64_t seed = 1;
  std::string out;                          // PNG
};

struct Figure3Result {
  std::vector<double> lengths_m;  // per start
  std::vector<size_t> waypoints;  // per start
  std::vector<int> arrived;       // particles that reached the goal, per start
};

// Throws std::runtime_error (a start or the goal blocked, no path, the file).
Figure3Result drawFigure3(const Figure3Options& options);

}  // namespace beft::figure

// Small hand-made maps that probe planners where potential fields struggle:
// a wall to go around, a U-shaped obstacle facing the start (a local minimum
// of the paper's field), a narrow gap off the straight line, and a comb
// whose teeth each form a small trap. Cell units, point robot.
#pragma once

#include "planners/geometry.hpp"
#include "planners/grid_map.hpp"

#include <string>
#include <utility>
#include <vector>

namespace beft::planners {

struct SyntheticCase {
  std::string name;
  GridMap map;
  std::vector<std::pair<Point2, Point2>> queries;  // (start, goal), cell centres
};

SyntheticCase simpleWallCase();
SyntheticCase uTrapCase();
SyntheticCase narrowGapCase();
SyntheticCase combCase();

// The traps the benchmark runs: U-trap, narrow gap, comb.
std::vector<SyntheticCase> syntheticTrapCases();

}  // namespace beft::planners

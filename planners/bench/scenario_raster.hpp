// The obstacle map of a scenario: every object with a visual (walls, cars,
// debris, persons at their start positions) drawn into a grid at the world's
// resolution, as the camera would eventually map it.
#pragma once

#include "planners/geometry.hpp"
#include "planners/grid_map.hpp"
#include "lib/scenario/scenario.hpp"

#include <string>

namespace beft::planners {

struct ScenarioMap {
  std::string name;
  GridMap grid;                 // row index along +y, cell (0,0) at world (0,0)
  double resolution = 0.1;      // [m/cell]
  Point2 robot_start;           // [cells]
  double robot_radius = 3.5;    // [cells]
};

// A cell is occupied when its centre lies within half a cell of a footprint.
ScenarioMap rasterizeScenario(const beft::scenario::Scenario& scenario);

}  // namespace beft::planners

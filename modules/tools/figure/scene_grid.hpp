// A scenario's ground truth as an obstacle grid at its map resolution: every
// object with a visual (boxes with their yaw, cylinders) except the persons,
// who are what the robot looks for, not what it plans around.
#pragma once

#include "planners/grid_map.hpp"
#include "lib/scenario/scenario.hpp"

namespace beft::figure {

planners::GridMap groundTruthGrid(const scenario::Scenario& scenario);

}  // namespace beft::figure

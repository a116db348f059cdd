// Ground footprints of visual objects: a box is a rectangle rotated by the
// object's yaw, a cylinder is a disc. Used to check the robot's start pose.
#pragma once

#include "lib/scenario/scenario.hpp"

namespace beft::scenario {

// Distance [m] from point (px, py) to the object's footprint; 0 inside it.
// Objects without a <visual> have no footprint: returns +infinity.
double distanceToFootprint(const Object& object, double px, double py);

}  // namespace beft::scenario

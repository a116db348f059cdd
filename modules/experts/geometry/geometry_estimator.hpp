// The low-level geometry expert's logic: distance d_i, azimuth alpha_i and
// elevation of every scene object relative to the robot, from ground truth
// and the robot state of one tick (reference points: object_geometry.hpp).
#pragma once

#include <beft/geometry_percepts_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

namespace beft::geometry {

// One percept per scene object, in scenario order; stamped with the scene's
// utime and tick.
geometry_percepts_t estimateGeometry(const scene_objects_t& scene, const robot_state_t& robot);

}  // namespace beft::geometry

// The low-level geometry expert's logic: distance d_i, azimuth alpha_i and
// elevation of scene objects relative to the robot, from ground truth and
// the robot state of one tick (reference points: object_geometry.hpp).
//
// Only of the objects another expert can ask about: those that sound now
// (audio reports them) and those in front of the camera (vision reports
// only what its view covers, and its field of view is under 180 degrees).
// An object wholly behind the camera's vertical plane, silent, is left
// out: in a district of 450 objects they were half of every message.
#pragma once

#include <beft/geometry_percepts_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

namespace beft::geometry {

// Whether the object sounds now or some part of it may be in front of the
// camera: its bounding circle reaches past the plane through the head centre
// across the nose, with room for the head's tilt (a camera looking down
// sees a little behind that plane near the ground) and half a metre more.
bool perceivable(const robot_state_t& robot, const scene_object_t& object);

// One percept per perceivable object (all objects with every_object), in
// scenario order; stamped with the scene's utime and tick.
geometry_percepts_t estimateGeometry(const scene_objects_t& scene, const robot_state_t& robot,
                                     bool every_object = false);

}  // namespace beft::geometry

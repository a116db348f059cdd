// Reference points shared by the low-level experts, so that every expert
// measures "the distance to object i" and "the azimuth of object i" alike:
//   platform centre: the robot's (x, y) on the ground (z = 0);
//   object centre:   the object's (x, y) at half its height above its base
//                    (z + size_z / 2); an object without a visual is a point
//                    at (x, y, z);
//   head centre:     above the platform centre at the camera height;
//   nose heading:    platform yaw + head yaw (degrees, CCW from +x);
//   ears:            +-0.09 m from the head centre along the head's lateral
//                    axis (left ear on the +90 deg side of the nose).
#pragma once

#include <Eigen/Core>
#include <beft/robot_state_t.hpp>
#include <beft/scene_object_t.hpp>

namespace beft::geometry {

inline constexpr double kEarOffset = 0.09;  // half the distance between the ears [m]

Eigen::Vector3d platformCentre(const robot_state_t& robot);
Eigen::Vector3d objectCentre(const scene_object_t& object);
Eigen::Vector3d headCentre(const robot_state_t& robot);
double noseHeadingDeg(const robot_state_t& robot);
Eigen::Vector3d leftEar(const robot_state_t& robot);
Eigen::Vector3d rightEar(const robot_state_t& robot);

bool hasVisual(const scene_object_t& object);
// The object emits sound now: it has an <acoustic> element and is active.
bool isSounding(const scene_object_t& object);

// d_i: 3-D distance from the platform centre to the object centre [m].
double objectDistance(const robot_state_t& robot, const scene_object_t& object);
// alpha_i: azimuth of the object centre relative to the nose, (-180, 180] deg,
// positive to the left.
double objectAzimuthDeg(const robot_state_t& robot, const scene_object_t& object);
// Elevation of the object centre seen from the head centre, relative to the
// head's pitch [deg], up positive.
double objectElevationDeg(const robot_state_t& robot, const scene_object_t& object);

}  // namespace beft::geometry

#include "lib/scene/object_geometry.hpp"

#include <cmath>

#include "lib/model/model.hpp"

namespace beft::geometry {

namespace {
constexpr double kDegToRad = M_PI / 180.0;
}

Eigen::Vector3d platformCentre(const robot_state_t& robot) { return {robot.x, robot.y, 0.0}; }

Eigen::Vector3d objectCentre(const scene_object_t& object) {
  const double half_height = hasVisual(object) ? 0.5 * object.size_z : 0.0;
  return {object.x, object.y, object.z + half_height};
}

Eigen::Vector3d headCentre(const robot_state_t& robot) {
  return {robot.x, robot.y, robot.camera_height};
}

double noseHeadingDeg(const robot_state_t& robot) { return robot.yaw + robot.head_yaw; }

Eigen::Vector3d leftEar(const robot_state_t& robot) {
  const double heading = noseHeadingDeg(robot) * kDegToRad;
  const Eigen::Vector3d left_axis(-std::sin(heading), std::cos(heading), 0.0);
  return headCentre(robot) + kEarOffset * left_axis;
}

Eigen::Vector3d rightEar(const robot_state_t& robot) {
  const double heading = noseHeadingDeg(robot) * kDegToRad;
  const Eigen::Vector3d left_axis(-std::sin(heading), std::cos(heading), 0.0);
  return headCentre(robot) - kEarOffset * left_axis;
}

bool hasVisual(const scene_object_t& object) {
  return object.shape == scene_object_t::SHAPE_BOX || object.shape == scene_object_t::SHAPE_CYLINDER;
}

bool isSounding(const scene_object_t& object) { return object.has_acoustic && object.sound_active; }

double objectDistance(const robot_state_t& robot, const scene_object_t& object) {
  const Eigen::Vector3d p = platformCentre(robot);
  const Eigen::Vector3d o = objectCentre(object);
  return model::distance(p.x(), p.y(), p.z(), o.x(), o.y(), o.z());
}

double objectAzimuthDeg(const robot_state_t& robot, const scene_object_t& object) {
  return model::azimuth(robot.x, robot.y, noseHeadingDeg(robot), object.x, object.y);
}

double objectElevationDeg(const robot_state_t& robot, const scene_object_t& object) {
  const Eigen::Vector3d offset = objectCentre(object) - headCentre(robot);
  const double horizontal = std::hypot(offset.x(), offset.y());
  return std::atan2(offset.z(), horizontal) / kDegToRad - robot.head_pitch;
}

}  // namespace beft::geometry

#include "experts/geometry/geometry_estimator.hpp"

#include "lib/scene/object_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace beft::geometry {

bool perceivable(const robot_state_t& robot, const scene_object_t& object) {
  if (isSounding(object)) return true;
  if (!hasVisual(object)) return false;
  constexpr double kDegToRad = M_PI / 180.0;
  const double heading = noseHeadingDeg(robot) * kDegToRad;
  const double ahead = (object.x - robot.x) * std::cos(heading) + (object.y - robot.y) * std::sin(heading);
  const double extent = 0.5 * std::hypot(object.size_x, object.size_y);
  const double tilt = std::min(std::abs(robot.head_pitch), 80.0) * kDegToRad;
  const double seen_behind = std::max(robot.camera_height, object.z + object.size_z) * std::tan(tilt);
  return ahead > -(extent + seen_behind + 0.5);
}

geometry_percepts_t estimateGeometry(const scene_objects_t& scene, const robot_state_t& robot, bool every_object) {
  geometry_percepts_t out{};
  out.utime = scene.utime;
  out.tick = scene.tick;
  for (const auto& object : scene.objects) {
    if (!every_object && !perceivable(robot, object)) continue;
    geometry_percept_t percept;
    percept.object_id = object.id;
    percept.distance = objectDistance(robot, object);
    percept.azimuth = objectAzimuthDeg(robot, object);
    percept.elevation = objectElevationDeg(robot, object);
    percept.acoustic = isSounding(object);
    out.percepts.push_back(percept);
  }
  out.num_percepts = static_cast<int32_t>(out.percepts.size());
  return out;
}

}  // namespace beft::geometry

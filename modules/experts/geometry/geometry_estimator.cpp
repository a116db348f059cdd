#include "geometry_estimator.hpp"

#include "object_geometry.hpp"

namespace beft::geometry {

geometry_percepts_t estimateGeometry(const scene_objects_t& scene, const robot_state_t& robot) {
  geometry_percepts_t out{};
  out.utime = scene.utime;
  out.tick = scene.tick;
  out.percepts.reserve(scene.objects.size());
  for (const auto& object : scene.objects) {
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

#include "experts/geometry/geometry_expert.hpp"

#include "lib/common/channels.hpp"
#include "experts/geometry/geometry_estimator.hpp"

namespace beft::geometry {

std::string GeometryExpert::description() const {
  return "Low-level geometry expert: for every scene object that sounds now or may be in front of the "
         "camera (every_object: all of them), the 3-D distance d_i from the "
         "platform centre (on the ground) to the object centre (half its height), the azimuth "
         "alpha_i relative to the nose (platform yaw + head yaw; (-180, 180] deg, positive to "
         "the left) and the elevation relative to the head pitch; flags objects that sound "
         "now. Reads GT_OBJECTS and ROBOT_STATE of the fired tick, writes GEOMETRY. "
         "To run it alone: start beft-world and feed FIRE tokens for 'geometry' (or run the "
         "arbiter), and watch GEOMETRY with lcm-spy.";
}

void GeometryExpert::declareParameters(DeclaredParameters& parameters) {
  parameters.declare("every_object", every_object_,
                     "a percept for every scene object, also the silent ones behind the camera, which no "
                     "expert reads (off: only those that sound now or may be in front of the camera)");
}

expert::Outcome GeometryExpert::fire(const expert::Firing& firing, expert::Output& out) {
  const auto* scene = scene_.ofTick(firing.tick);
  const auto* robot = robot_.ofTick(firing.tick);
  if (scene == nullptr || robot == nullptr)
    return expert::Outcome::failure(std::string("no ") + (scene == nullptr ? "GT_OBJECTS" : "ROBOT_STATE") +
                                    " for tick " + std::to_string(firing.tick));
  geometry_out_.publish(out, estimateGeometry(*scene, *robot, every_object_));
  return expert::Outcome::success();
}

}  // namespace beft::geometry

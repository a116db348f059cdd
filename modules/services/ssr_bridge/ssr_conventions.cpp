#include "services/ssr_bridge/ssr_conventions.hpp"

#include <cmath>

namespace beft::ssr_bridge {

double normalisedDegrees(double degrees) {
  if (!std::isfinite(degrees)) return 0.0;
  double a = std::fmod(degrees, 360.0);
  if (a < 0) a += 360.0;
  return a >= 360.0 ? 0.0 : a;  // fmod of a tiny negative number plus 360 rounds to 360
}

ListenerPose listenerPose(const beft::robot_state_t& robot) {
  ListenerPose pose;
  pose.x = robot.x;
  pose.y = robot.y;
  pose.azimuth = normalisedDegrees(robot.yaw + robot.head_yaw);
  return pose;
}

double volumeDecibels(double linear_level) {
  if (!(linear_level > 0) || !std::isfinite(linear_level)) return kSilentVolumeDb;
  return std::max(kSilentVolumeDb, 20.0 * std::log10(linear_level));
}

}  // namespace beft::ssr_bridge

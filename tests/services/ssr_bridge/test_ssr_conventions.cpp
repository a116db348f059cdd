#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "services/ssr_bridge/ssr_conventions.hpp"

using namespace beft::ssr_bridge;

namespace {

beft::robot_state_t robotAt(double x, double y, double yaw, double head_yaw) {
  beft::robot_state_t robot{};
  robot.x = x;
  robot.y = y;
  robot.yaw = yaw;
  robot.head_yaw = head_yaw;
  return robot;
}

// Where a source at (sx, sy) appears to a listener, counter-clockwise from
// the nose, in SSR's own terms: its azimuth counts from +x, as the bearing does.
double bearingFromNose(const ListenerPose& listener, double sx, double sy) {
  const double bearing = std::atan2(sy - listener.y, sx - listener.x) * 180.0 / M_PI;
  return normalisedDegrees(bearing - listener.azimuth);
}

}  // namespace

TEST(SsrConventions, RobotFacingPlusYWithTheHeadTurned30DegreesLeft) {
  const ListenerPose pose = listenerPose(robotAt(4, -2, 90, 30));
  EXPECT_DOUBLE_EQ(pose.x, 4);
  EXPECT_DOUBLE_EQ(pose.y, -2);
  EXPECT_NEAR(pose.azimuth, 120, 1e-9);  // SSR: 90 looks along +y, a further 30 to the left
}

TEST(SsrConventions, SSRsDefaultOrientationIsARobotFacingPlusY) {
  EXPECT_NEAR(listenerPose(robotAt(0, 0, 90, 0)).azimuth, 90, 1e-9);
  EXPECT_NEAR(listenerPose(robotAt(0, 0, 0, 0)).azimuth, 0, 1e-9);  // nose along +x
}

TEST(SsrConventions, ASourceOnTheLeftOfTheHeadIsOnTheLeftOfTheListener) {
  // Platform facing -x, head turned 90 deg to the right: the nose looks along +y;
  // a source at -x is then on the listener's left (+90 from the nose).
  const ListenerPose pose = listenerPose(robotAt(1, 1, 180, -90));
  EXPECT_NEAR(pose.azimuth, 90, 1e-9);
  EXPECT_NEAR(bearingFromNose(pose, -5, 1), 90, 1e-9);
  EXPECT_NEAR(bearingFromNose(pose, 1, 7), 0, 1e-9);
}

TEST(SsrConventions, AzimuthsAreBroughtIntoZeroTo360) {
  EXPECT_NEAR(listenerPose(robotAt(0, 0, -170, -30)).azimuth, 160, 1e-9);
  EXPECT_NEAR(listenerPose(robotAt(0, 0, 350, 20)).azimuth, 10, 1e-9);
  EXPECT_NEAR(normalisedDegrees(-720), 0, 1e-12);
  EXPECT_GE(normalisedDegrees(-1e-15), 0.0);
  EXPECT_LT(normalisedDegrees(-1e-15), 360.0);
  EXPECT_EQ(normalisedDegrees(std::numeric_limits<double>::quiet_NaN()), 0.0);
}

TEST(SsrConventions, VolumeIsTheLevelInDecibelsWithAFloorForSilence) {
  EXPECT_NEAR(volumeDecibels(1.0), 0.0, 1e-12);
  EXPECT_NEAR(volumeDecibels(0.5), -6.0206, 1e-4);
  EXPECT_NEAR(volumeDecibels(2.0), 6.0206, 1e-4);
  EXPECT_EQ(volumeDecibels(0.0), kSilentVolumeDb);
  EXPECT_EQ(volumeDecibels(-1.0), kSilentVolumeDb);
  EXPECT_EQ(volumeDecibels(1e-9), kSilentVolumeDb);
  EXPECT_EQ(volumeDecibels(std::numeric_limits<double>::infinity()), kSilentVolumeDb);
}

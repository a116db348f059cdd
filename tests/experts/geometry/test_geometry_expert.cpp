// Geometry expert logic: distance, azimuth (with wrap) and elevation against
// hand-computed numbers.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry_estimator.hpp"
#include "object_geometry.hpp"
#include "scene_builders.hpp"

using namespace beft;

namespace {
const geometry_percept_t& percept(const geometry_percepts_t& out, const std::string& id) {
  for (const auto& p : out.percepts)
    if (p.object_id == id) return p;
  throw std::runtime_error("no percept for " + id);
}
}  // namespace

TEST(GeometryExpert, ObjectStraightLeftIsPlus90AndDistanceGoesToHalfHeight) {
  const auto s = test::scene({test::cylinderObject("victim", "person", 5, 8, 0.3, 1.8)});
  const auto out = geometry::estimateGeometry(s, test::robot(5, 4, 0));
  ASSERT_EQ(out.num_percepts, 1);
  EXPECT_NEAR(percept(out, "victim").azimuth, 90.0, 1e-9);
  // Platform centre (5, 4, 0) to object centre (5, 8, 0.9).
  EXPECT_NEAR(percept(out, "victim").distance, std::sqrt(16.0 + 0.81), 1e-9);
}

TEST(GeometryExpert, AzimuthIsRelativeToPlatformPlusHeadYaw) {
  const auto s = test::scene({test::pointObject("radio", "siren", 5, 8)});
  EXPECT_NEAR(percept(geometry::estimateGeometry(s, test::robot(5, 4, 45, 45)), "radio").azimuth, 0.0, 1e-9);
  EXPECT_NEAR(percept(geometry::estimateGeometry(s, test::robot(5, 4, 90, -30)), "radio").azimuth, 30.0, 1e-9);
  // Straight right of the nose.
  EXPECT_NEAR(percept(geometry::estimateGeometry(s, test::robot(5, 4, 180)), "radio").azimuth, -90.0, 1e-9);
}

TEST(GeometryExpert, BehindRightAndWrapAround180) {
  const auto s = test::scene({test::pointObject("a", "car", 4, 3), test::pointObject("b", "car", 4, 5),
                              test::pointObject("c", "car", 3, 4)});
  const auto r = test::robot(5, 4, 0);
  const auto out = geometry::estimateGeometry(s, r);
  EXPECT_NEAR(percept(out, "a").azimuth, -135.0, 1e-9);  // behind right
  EXPECT_NEAR(percept(out, "b").azimuth, 135.0, 1e-9);   // behind left
  EXPECT_NEAR(percept(out, "c").azimuth, 180.0, 1e-9);   // straight behind: +180, never -180
  // Nose at 170 deg, object at world bearing -170 deg: 20 deg to the left across the wrap.
  const double bearing = -170.0 * M_PI / 180.0;
  const auto s2 = test::scene({test::pointObject("d", "car", 5 + 3 * std::cos(bearing), 4 + 3 * std::sin(bearing))});
  EXPECT_NEAR(percept(geometry::estimateGeometry(s2, test::robot(5, 4, 150, 20)), "d").azimuth, 20.0, 1e-9);
  EXPECT_NEAR(percept(geometry::estimateGeometry(s2, test::robot(5, 4, -150)), "d").azimuth, -20.0, 1e-9);
}

TEST(GeometryExpert, ElevationFromTheHeadRelativeToItsPitch) {
  // Box 3.2 m tall: centre at 1.6 m, the camera height: level with the head.
  const auto s = test::scene({test::boxObject("wall", "wall", 9, 4, 0, 0.2, 4, 3.2),
                              test::pointObject("low", "siren", 6.6, 4, 0)});
  const auto level = geometry::estimateGeometry(s, test::robot(5, 4, 0));
  EXPECT_NEAR(percept(level, "wall").elevation, 0.0, 1e-9);
  EXPECT_NEAR(percept(level, "low").elevation, -45.0, 1e-9);  // 1.6 m down over 1.6 m
  const auto pitched = geometry::estimateGeometry(s, test::robot(5, 4, 0, 0, 10));
  EXPECT_NEAR(percept(pitched, "wall").elevation, -10.0, 1e-9);
}

TEST(GeometryExpert, FlagsOnlyObjectsThatSoundNowAndKeepsSceneOrder) {
  auto silent = test::sounding(test::pointObject("radio", "siren", 1, 1), "ringing");
  silent.sound_active = false;
  const auto s = test::scene({test::sounding(test::cylinderObject("v", "person", 2, 2, 0.3, 1.8), "yelling"), silent,
                              test::boxObject("w", "wall", 3, 3, 0, 1, 1, 1)});
  const auto out = geometry::estimateGeometry(s, test::robot(5, 5, 0));
  ASSERT_EQ(out.num_percepts, 3);
  EXPECT_EQ(out.percepts[0].object_id, "v");
  EXPECT_EQ(out.percepts[1].object_id, "radio");
  EXPECT_EQ(out.percepts[2].object_id, "w");
  EXPECT_TRUE(out.percepts[0].acoustic);
  EXPECT_FALSE(out.percepts[1].acoustic);
  EXPECT_FALSE(out.percepts[2].acoustic);
  EXPECT_EQ(out.tick, s.tick);
  EXPECT_EQ(out.utime, s.utime);
}

TEST(GeometryExpert, EarsSitBesideTheHeadAlongItsLateralAxis) {
  const auto r = test::robot(5, 4, 90, 0);  // nose towards +y: left ear towards -x
  EXPECT_NEAR((geometry::leftEar(r) - Eigen::Vector3d(4.91, 4, 1.6)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((geometry::rightEar(r) - Eigen::Vector3d(5.09, 4, 1.6)).norm(), 0.0, 1e-12);
}

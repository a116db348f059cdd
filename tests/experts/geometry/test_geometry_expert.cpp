// Geometry expert logic: distance, azimuth (with wrap) and elevation against
// hand-computed numbers; which objects it leaves out (silent ones behind the
// camera), never one that vision can report.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "experts/geometry/geometry_estimator.hpp"
#include "lib/scene/object_geometry.hpp"
#include "lib/scene/camera_model.hpp"
#include "lib/scene/ray_caster.hpp"
#include "lib/scene/scene_geometry.hpp"
#include "tests/experts/support/scene_builders.hpp"

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
  EXPECT_NEAR(percept(geometry::estimateGeometry(s, test::robot(5, 4, 45, 45), true), "radio").azimuth, 0.0, 1e-9);
  EXPECT_NEAR(percept(geometry::estimateGeometry(s, test::robot(5, 4, 90, -30), true), "radio").azimuth, 30.0, 1e-9);
  // Straight right of the nose.
  EXPECT_NEAR(percept(geometry::estimateGeometry(s, test::robot(5, 4, 180), true), "radio").azimuth, -90.0, 1e-9);
}

TEST(GeometryExpert, BehindRightAndWrapAround180) {
  const auto s = test::scene({test::pointObject("a", "car", 4, 3), test::pointObject("b", "car", 4, 5),
                              test::pointObject("c", "car", 3, 4)});
  const auto r = test::robot(5, 4, 0);
  const auto out = geometry::estimateGeometry(s, r, /*every_object=*/true);
  EXPECT_NEAR(percept(out, "a").azimuth, -135.0, 1e-9);  // behind right
  EXPECT_NEAR(percept(out, "b").azimuth, 135.0, 1e-9);   // behind left
  EXPECT_NEAR(percept(out, "c").azimuth, 180.0, 1e-9);   // straight behind: +180, never -180
  // Nose at 170 deg, object at world bearing -170 deg: 20 deg to the left across the wrap.
  const double bearing = -170.0 * M_PI / 180.0;
  const auto s2 = test::scene({test::pointObject("d", "car", 5 + 3 * std::cos(bearing), 4 + 3 * std::sin(bearing))});
  EXPECT_NEAR(percept(geometry::estimateGeometry(s2, test::robot(5, 4, 150, 20), true), "d").azimuth, 20.0, 1e-9);
  EXPECT_NEAR(percept(geometry::estimateGeometry(s2, test::robot(5, 4, -150), true), "d").azimuth, -20.0, 1e-9);
}

TEST(GeometryExpert, ElevationFromTheHeadRelativeToItsPitch) {
  // Box 3.2 m tall: centre at 1.6 m, the camera height: level with the head.
  const auto s = test::scene({test::boxObject("wall", "wall", 9, 4, 0, 0.2, 4, 3.2),
                              test::pointObject("low", "siren", 6.6, 4, 0)});
  const auto level = geometry::estimateGeometry(s, test::robot(5, 4, 0), true);
  EXPECT_NEAR(percept(level, "wall").elevation, 0.0, 1e-9);
  EXPECT_NEAR(percept(level, "low").elevation, -45.0, 1e-9);  // 1.6 m down over 1.6 m
  const auto pitched = geometry::estimateGeometry(s, test::robot(5, 4, 0, 0, 10), true);
  EXPECT_NEAR(percept(pitched, "wall").elevation, -10.0, 1e-9);
}

TEST(GeometryExpert, FlagsOnlyObjectsThatSoundNowAndKeepsSceneOrder) {
  auto silent = test::sounding(test::pointObject("radio", "siren", 1, 1), "ringing");
  silent.sound_active = false;
  const auto s = test::scene({test::sounding(test::cylinderObject("v", "person", 2, 2, 0.3, 1.8), "yelling"), silent,
                              test::boxObject("w", "wall", 3, 3, 0, 1, 1, 1)});
  const auto out = geometry::estimateGeometry(s, test::robot(5, 5, 0), true);
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

TEST(GeometryExpert, LeavesOutSilentObjectsBehindTheCameraOnly) {
  auto silent_radio = test::sounding(test::pointObject("silent_radio", "siren", 1, 5), "ringing");
  silent_radio.sound_active = false;
  const auto s = test::scene({
      test::sounding(test::cylinderObject("caller_behind", "person", 1, 5, 0.3, 1.8), "yelling"),
      test::cylinderObject("person_behind", "person", 1, 5, 0.3, 1.8),
      test::cylinderObject("person_ahead", "person", 9, 5, 0.3, 1.8),
      test::cylinderObject("person_beside", "person", 5, 9, 0.3, 1.8),  // at +90 deg: its edge is ahead
      test::boxObject("wall_behind", "wall", 2, 5, 90, 0.2, 2, 3),  // 3 m behind, 1 m either side
      test::boxObject("wall_across", "wall", 3.5, 5, 0, 4, 0.2, 3),       // reaches to 0.5 m behind the head
      silent_radio});
  const auto out = geometry::estimateGeometry(s, test::robot(5, 5, 0));
  std::vector<std::string> kept;
  for (const auto& p : out.percepts) kept.push_back(p.object_id);
  EXPECT_EQ(kept, (std::vector<std::string>{"caller_behind", "person_ahead", "person_beside", "wall_across"}));
  EXPECT_EQ(out.num_percepts, 4);
  // Turning the head brings what is behind the platform in front of the
  // camera (and person_ahead behind it).
  EXPECT_EQ(geometry::estimateGeometry(s, test::robot(5, 5, 0, 180)).num_percepts, 5);
  EXPECT_EQ(geometry::estimateGeometry(s, test::robot(5, 5, 0), true).num_percepts, 7);
}

// Vision lists every object whose shape falls into the image (expected
// pixels > 0, counted as the vision expert counts them); each must have a
// geometry percept, or its labels would be skipped. Random scenes around
// the robot, a wide camera, the head turned and tilted every way.
TEST(GeometryExpert, EveryObjectVisionCanReportHasAPercept) {
  std::mt19937 random(11);
  auto uniform = [&random](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  int left_out = 0, objects = 0;
  for (int trial = 0; trial < 150; ++trial) {
    std::vector<scene_object_t> shapes;
    for (int i = 0; i < 30; ++i) {
      const std::string id = "o" + std::to_string(i);
      const double x = uniform(-25, 25), y = uniform(-25, 25);
      shapes.push_back(i % 2 == 0 ? test::boxObject(id, "wall", x, y, uniform(-180, 180), uniform(0.1, 12),
                                                    uniform(0.1, 3), uniform(0.2, 4))
                                  : test::cylinderObject(id, "person", x, y, uniform(0.1, 1.5), uniform(0.3, 3)));
    }
    const auto s = test::scene(shapes, 0, 60, 60);
    const auto robot = test::robot(uniform(-2, 2), uniform(-2, 2), uniform(-180, 180), uniform(-120, 120),
                                   uniform(-40, 30));
    camera::CameraIntrinsics intrinsics;
    intrinsics.fov_deg = trial % 3 == 0 ? 170 : 90;
    camera::RayCaster caster;
    const std::vector<int> expected =
        caster.expectedPixelsInView(camera::SceneGeometry::fromMessage(s), camera::cameraOnRobot(robot, intrinsics));
    const auto out = geometry::estimateGeometry(s, robot);
    std::set<std::string> kept;
    for (const auto& p : out.percepts) kept.insert(p.object_id);
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
      if (i < expected.size() && expected[i] > 0) {
        EXPECT_TRUE(kept.count(s.objects[i].id)) << "trial " << trial << ": " << s.objects[i].id << " in view ("
                                                 << expected[i] << " px) but left out";
      }
    }
    left_out += static_cast<int>(s.objects.size() - kept.size());
    objects += static_cast<int>(s.objects.size());
  }
  EXPECT_GT(left_out, objects / 4);  // and it does leave out a good part
}

// Whether the robot could ever see an object, on the ground truth: 3-D
// segments against boxes and cylinders, a camera at 1.6 m seeing over low
// rubble but not through a tall wall, a siren seen on its own pole.
#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "lib/scenario/sight_lines.hpp"
#include "tests/lib/scenario/solid_objects.hpp"

namespace beft::scenario {
namespace {

using test_objects::solid;

Object pole(const std::string& id, double x, double y, double radius, double height) {
  return test_objects::cylinder(id, "wall", x, y, radius, height);
}

// A 20 x 20 m world, the robot at (2, 2), a person at (15, 15).
Scenario world() {
  Scenario s;
  s.world.width = 20;
  s.world.height = 20;
  s.robot.x = 2;
  s.robot.y = 2;
  s.objects.push_back(solid("victim", "person", 15, 15, 0.5, 0.5, 1.7));
  return s;
}

// Four walls of the given height round (15, 15), 3 m from it.
void surround(Scenario& s, double height) {
  s.objects.push_back(solid("n", "wall", 15, 18, 6.2, 0.2, height));
  s.objects.push_back(solid("s", "wall", 15, 12, 6.2, 0.2, height));
  s.objects.push_back(solid("e", "wall", 18, 15, 0.2, 6.2, height));
  s.objects.push_back(solid("w", "wall", 12, 15, 0.2, 6.2, height));
}

TEST(SightLines, SegmentsAgainstBoxesAndCylinders) {
  const Object wall = solid("w", "wall", 5, 5, 0.2, 4, 2);  // x in [4.9, 5.1], y in [3, 7], z in [0, 2]
  const double a[3] = {3, 5, 1.6}, b[3] = {7, 5, 1.6}, over_a[3] = {3, 5, 2.5}, over_b[3] = {7, 5, 2.5};
  EXPECT_TRUE(segmentHitsSolid(wall, a, b));
  EXPECT_FALSE(segmentHitsSolid(wall, over_a, over_b));
  const double beside_a[3] = {3, 7.5, 1}, beside_b[3] = {7, 7.5, 1};
  EXPECT_FALSE(segmentHitsSolid(wall, beside_a, beside_b));
  const double short_b[3] = {4.8, 5, 1.6};
  EXPECT_FALSE(segmentHitsSolid(wall, a, short_b)) << "ends before the wall";
  const Object post = pole("p", 5, 5, 0.3, 1.0);
  EXPECT_TRUE(segmentHitsSolid(post, std::array<double, 3>{3, 5, 0.5}.data(), std::array<double, 3>{7, 5, 0.5}.data()));
  EXPECT_FALSE(segmentHitsSolid(post, a, b)) << "over the top";
  EXPECT_FALSE(segmentHitsSolid(post, std::array<double, 3>{3, 5.4, 0.5}.data(),
                                std::array<double, 3>{7, 5.4, 0.5}.data()))
      << "beside it";
}

TEST(SightLines, APersonWalledInByTallWallsCannotBeSeenOverLowOnesItCan) {
  Scenario open = world();
  EXPECT_TRUE(unseeableObjects(open).empty());
  Scenario walled = world();
  surround(walled, 2.5);
  EXPECT_EQ(unseeableObjects(walled), std::vector<std::string>{"victim"});
  Scenario rubble = world();
  surround(rubble, 1.0);  // the camera at 1.6 m looks over it
  const SightLines lines(rubble);
  const auto place = lines.placeThatSees(rubble.objects.front());
  ASSERT_TRUE(place.has_value());
  EXPECT_GE(std::hypot(place->x - 15, place->y - 15), 1.5);
  EXPECT_LE(std::hypot(place->x - 15, place->y - 15), 6.0);
  EXPECT_TRUE(lines.reachable().isReachableAt(place->x, place->y));
}

TEST(SightLines, AnObjectOnItsPoleIsSeenAndWallsNeedNotBe) {
  Scenario s = world();
  s.objects.push_back(solid("siren1", "siren", 8, 8, 0.3, 0.3, 0.3, 1.8));
  s.objects.push_back(pole("siren1_pole", 8, 8, 0.2, 1.8));
  surround(s, 2.5);
  EXPECT_EQ(unseeableObjects(s), std::vector<std::string>{"victim"}) << "the walls round it are not asked for";
}

}  // namespace
}  // namespace beft::scenario

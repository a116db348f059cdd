// Path efficiency per victim (SPL per person) on tiny scenes whose shortest
// paths can be worked out by hand.
#include <array>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "lib/report/report_json.hpp"
#include "lib/report/run_record.hpp"
#include "lib/report/run_scoring.hpp"
#include "tools/report/path_efficiency.hpp"

namespace beft::report {
namespace {

// A 10 x 8 m yard at 0.1 m, the robot at (1.05, 2.05), a person at (9.05,
// 2.05), a camera that sees 3.1 m: in the open, the nearest viewpoint is
// (6.05, 2.05), 3 m short of the person, 5 m straight ahead of the robot.
scenario::Scenario yard() {
  scenario::Scenario s;
  s.name = "spl-yard";
  s.world.width = 10;
  s.world.height = 8;
  s.world.resolution = 0.1;
  s.robot.x = 1.05;
  s.robot.y = 2.05;
  s.robot.radius = 0.35;
  s.robot.camera.range = 3.1;
  scenario::Object person;
  person.id = "p1";
  person.label = "person";
  person.x = 9.05;
  person.y = 2.05;
  scenario::Visual body;
  body.shape = scenario::Visual::Shape::Cylinder;
  body.radius = 0.3;
  body.height = 1.8;
  person.visual = body;
  s.objects.push_back(person);
  return s;
}

// A wall from the bottom edge to y = 5 m at x = 5 m, 0.2 m thick: the robot
// must go round its top end.
scenario::Scenario yardWithWall() {
  scenario::Scenario s = yard();
  scenario::Object wall;
  wall.id = "w1";
  wall.label = "wall";
  wall.x = 5.0;
  wall.y = 2.5;
  scenario::Visual box;
  box.size_x = 0.2;
  box.size_y = 5.0;
  box.size_z = 2.5;
  wall.visual = box;
  s.objects.push_back(wall);
  return s;
}

// The robot drives along +x at 1 m/s from the start (0.1 m per tick); the
// person p1 is found at found_at_s; a second person, p2, is missed.
RunRecord drive(double seconds) {
  RunRecord record;
  for (int k = 0; k * 0.1 <= seconds + 1e-9; ++k) {
    RobotSample sample;
    sample.tick = k;
    sample.t = k * 0.1;
    sample.x = 1.05 + 0.1 * k;
    sample.y = 2.05;
    sample.path_length = 0.1 * k;
    record.robot.push_back(sample);
  }
  return record;
}

RunReport foundAt(double found_at_s) {
  RunReport report;
  report.persons = 2;
  VictimEntry victim;
  victim.object = "p1";
  victim.found_at_s = found_at_s;
  report.victims.push_back(victim);
  report.missed = {"p2"};
  return report;
}

TEST(PathEfficiency, IsTheShortestOverTheLongerOfShortestAndDriven) {
  EXPECT_DOUBLE_EQ(pathEfficiency(5.0, 8.0), 0.625);
  EXPECT_DOUBLE_EQ(pathEfficiency(5.0, 4.8), 1.0);  // drove a taut line shorter than the grid's
  EXPECT_DOUBLE_EQ(pathEfficiency(0.0, 0.0), 1.0);  // seen from the start
  EXPECT_DOUBLE_EQ(pathEfficiency(0.0, 3.0), 0.0);
}

TEST(PathEfficiency, InTheOpenTheShortestPathEndsWhereTheCameraFirstReaches) {
  const RunRecord record = drive(10.0);
  RunReport report = foundAt(8.0);  // 8 m driven by then
  scorePathEfficiency(record, yard(), PathEfficiencyOptions{}, report);
  const VictimEntry& v = report.victims[0];
  ASSERT_TRUE(v.shortest_path_m.has_value());
  EXPECT_NEAR(*v.shortest_path_m, 5.0, 1e-9);  // 50 cells straight along +x
  EXPECT_NEAR(*v.driven_m, 8.0, 1e-9);
  EXPECT_NEAR(*v.path_efficiency, 0.625, 1e-9);
  ASSERT_TRUE(report.path_efficiency_mean.has_value());
  EXPECT_NEAR(*report.path_efficiency_mean, 0.625 / 2, 1e-9);  // p2, missed, counts 0
  const auto json = toJson(report);
  EXPECT_NEAR(json["victims"][0]["path_efficiency"].get<double>(), 0.625, 1e-3);
  EXPECT_NEAR(json["victims"][0]["shortest_path_m"].get<double>(), 5.0, 1e-3);
  EXPECT_NEAR(json["victims"][0]["driven_m"].get<double>(), 8.0, 1e-3);
  EXPECT_NEAR(json["path_efficiency_mean"].get<double>(), 0.3125, 1e-3);
}

TEST(PathEfficiency, AWallMakesTheRobotGoRoundItsEnd) {
  const RunRecord record = drive(20.0);
  RunReport report = foundAt(15.0);
  scorePathEfficiency(record, yardWithWall(), PathEfficiencyOptions{}, report);
  const VictimEntry& v = report.victims[0];
  ASSERT_TRUE(v.shortest_path_m.has_value());
  // Round the wall's top end (5, 5) kept 0.5 m clear (the inflation), then
  // down to a viewpoint that sees past the wall: at least the two straight
  // legs from the start to (5, 5.5) and from there to the nearest point 3.1 m
  // from the person. A* pulled taut adds only what the cells round the end
  // and the viewpoints' 0.25 m grid cost.
  const double to_corner = std::hypot(5.0 - 1.05, 5.5 - 2.05);
  const double corner_to_person = std::hypot(9.05 - 5.0, 2.05 - 5.5);
  const double lower = to_corner + corner_to_person - 3.1;
  EXPECT_GE(*v.shortest_path_m, lower - 0.15);  // cell centres may graze the inflated end
  EXPECT_LE(*v.shortest_path_m, lower + 0.5);
  EXPECT_NEAR(*v.path_efficiency, *v.shortest_path_m / 15.0, 1e-9);
}

TEST(PathEfficiency, APersonNoViewpointOfWhichCanBeReachedIsLeftOut) {
  scenario::Scenario boxed = yard();
  // Walls all round the person, 1 m away: nothing sees in, nothing gets in.
  for (const auto& [x, y, sx, sy] : {std::array<double, 4>{9.05, 1.0, 2.4, 0.2}, {9.05, 3.1, 2.4, 0.2},
                                     {7.9, 2.05, 0.2, 2.4}}) {
    scenario::Object wall;
    wall.id = "w" + std::to_string(boxed.objects.size());
    wall.label = "wall";
    wall.x = x;
    wall.y = y;
    scenario::Visual box;
    box.size_x = sx;
    box.size_y = sy;
    box.size_z = 2.5;
    wall.visual = box;
    boxed.objects.push_back(wall);
  }
  RunReport report = foundAt(8.0);
  scorePathEfficiency(drive(10.0), boxed, PathEfficiencyOptions{}, report);
  EXPECT_FALSE(report.victims[0].path_efficiency.has_value());
  ASSERT_TRUE(report.path_efficiency_mean.has_value());
  EXPECT_DOUBLE_EQ(*report.path_efficiency_mean, 0.0);  // p2 missed, p1 not counted
  EXPECT_FALSE(toJson(report)["victims"][0].contains("path_efficiency"));
}

}  // namespace
}  // namespace beft::report

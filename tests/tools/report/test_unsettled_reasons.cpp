// Why a hypothesis was left unsettled: a person walled in by tall walls is
// seen from nowhere on the ground truth; a car in the open is seen from a
// reachable place, and what the exploration said of it when it stopped is
// quoted.
#include <tuple>

#include <gtest/gtest.h>

#include "tests/lib/scenario/solid_objects.hpp"
#include "tools/report/unsettled_reasons.hpp"

namespace beft::report {
namespace {

using scenario::test_objects::solid;

TEST(UnsettledReasons, WhetherAnyPlaceSeesItAndWhatTheExplorationSaid) {
  scenario::Scenario s;
  s.world.width = 30;
  s.world.height = 20;
  s.robot.x = 2;
  s.robot.y = 2;
  s.objects.push_back(solid("victim", "person", 15, 15, 0.5, 0.5, 1.7));
  for (const auto& [id, x, y, sx, sy] : {std::tuple{"n", 15.0, 18.0, 6.2, 0.2}, {"s", 15.0, 12.0, 6.2, 0.2},
                                         {"e", 18.0, 15.0, 0.2, 6.2}, {"w", 12.0, 15.0, 0.2, 6.2}})
    s.objects.push_back(solid(id, "wall", x, y, sx, sy, 2.5));
  s.objects.push_back(solid("car1", "car", 25, 5, 4.5, 1.8, 1.5));
  RunReport report;
  report.unsettled = {"victim", "car1", "ghost"};
  report.end_reason =
      "nothing left to explore: 3 hypotheses (0 verified, 0 falsified, 2 without a reachable viewpoint), no reachable "
      "frontier left; victim: no reachable viewpoint on the known map; car1: given up after 4 viewpoints, the last: "
      "timed out";
  explainUnsettled(s, report);
  ASSERT_EQ(report.unsettled_why.size(), 3u);
  EXPECT_EQ(report.unsettled_why["victim"],
            "no place the robot can reach sees it on the ground truth (within 1.5-6 m, camera at 1.6 m); the "
            "exploration: no reachable viewpoint on the known map");
  const std::string& car = report.unsettled_why["car1"];
  EXPECT_EQ(car.rfind("seen on the ground truth from (", 0), 0u) << car;
  EXPECT_NE(car.find("; the exploration: given up after 4 viewpoints, the last: timed out"), std::string::npos) << car;
  EXPECT_EQ(report.unsettled_why["ghost"], "no object of the scenario has this id");
}

}  // namespace
}  // namespace beft::report

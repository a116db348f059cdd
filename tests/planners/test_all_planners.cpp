// Every planner, on the same maps, returns a path that is collision-free on
// the inflated map, checked cell by cell (not with the planners' own checker).
#include "planners/movingai.hpp"
#include "planners/ompl_planner.hpp"
#include "planners/path_tools.hpp"
#include "planners/planner_factory.hpp"
#include "tests/planners/planner_test_support.hpp"
#include "planners/synthetic_maps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace beft::planners {
namespace {

struct Problem {
  std::string name;
  std::shared_ptr<PlanningMap> map;
  std::vector<std::pair<Point2, Point2>> queries;
};

std::vector<Problem> problems() {
  std::vector<Problem> out;
  const SyntheticCase comb = combCase();
  // Radius 1.2 cells: the teeth grow, the gaps between them shrink to 3 cells.
  out.push_back({"comb r=1.2", std::make_shared<PlanningMap>(comb.map, 1.2), {comb.queries[0]}});
  const SyntheticCase gap = narrowGapCase();
  out.push_back({"narrow gap", std::make_shared<PlanningMap>(gap.map, 0.0), {gap.queries[0]}});
  const std::string file = test::movingAiFile("random-32-32-20.map");
  const auto queries = loadMovingAiScenario(file + ".scen");
  Problem p{"random-32-32-20", std::make_shared<PlanningMap>(loadMovingAiMap(file), 0.0), {}};
  for (size_t i : {queries.size() / 2, queries.size() - 1}) {
    p.queries.push_back({cellCentre(queries[i].start_x, queries[i].start_y), cellCentre(queries[i].goal_x, queries[i].goal_y)});
  }
  out.push_back(p);
  return out;
}

class EveryPlanner : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryPlanner, PathsAreCollisionFreeOnTheInflatedMapCellByCell) {
  PlannerConfig config;
  config.seed = 3;
  auto planner = makePlanner(GetParam(), config);
  EXPECT_EQ(planner->name(), GetParam());
  // Anytime planners return their first path here: this test is about
  // collisions, not about how far they improve.
  if (auto* ompl_planner = dynamic_cast<OmplPlanner*>(planner.get())) ompl_planner->setStopAtFirstSolution(true);
  for (const Problem& problem : problems()) {
    SCOPED_TRACE(problem.name);
    planner->setup(problem.map);
    for (const auto& [start, goal] : problem.queries) {
      const PlanResult r = planner->solve(start, goal, Deadline::after(10.0));
      ASSERT_TRUE(r.success) << r.message;
      EXPECT_EQ(test::findCollision(problem.map->inflated(), r.raw_path), "");
      EXPECT_EQ(test::findCollision(problem.map->inflated(), r.path), "");
      EXPECT_NEAR(r.path.front().x, start.x, 1e-9);
      EXPECT_NEAR(r.path.front().y, start.y, 1e-9);
      EXPECT_NEAR(r.path.back().x, goal.x, 1e-9);
      EXPECT_NEAR(r.path.back().y, goal.y, 1e-9);
      EXPECT_LE(r.length(), pathLength(r.raw_path) + 1e-9);  // the tightening never lengthens
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Planners, EveryPlanner, ::testing::ValuesIn(plannerNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name;
                           for (char c : info.param) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

TEST(PlannerFactory, RefusesUnknownNamesAndParameters) {
  EXPECT_THROW(makePlanner("dijkstra"), std::invalid_argument);
  EXPECT_THROW(makePlanner("ompl:Nonsense"), std::invalid_argument);
  PlannerConfig config;
  config.pf_params = {{"particles", "-3"}};
  EXPECT_THROW(makePlanner("pf", config), std::invalid_argument);
  EXPECT_THROW(splitParameter("particles"), std::invalid_argument);
  EXPECT_EQ(splitParameter("sigma=2.5").second, "2.5");
}

TEST(PathTools, TighteningApproachesTheAnyAngleOptimum) {
  // Around a single square obstacle the taut path is known exactly.
  GridMap grid(40, 40);
  grid.fillRect(15, 15, 24, 24);
  const PlanningMap map(grid, 0.0);
  // A staircase detour below the block, from (5.5, 20.5) to (34.5, 20.5).
  Path detour{{5.5, 20.5}};
  for (int x = 6; x <= 14; ++x) detour.push_back({x + 0.5, 20.5 - (x - 5)});
  for (int x = 15; x <= 25; ++x) detour.push_back({x + 0.5, 11.5});
  for (int x = 26; x <= 34; ++x) detour.push_back({x + 0.5, 11.5 + (x - 25)});
  ASSERT_TRUE(pathFree(map, detour));
  const Path taut = tightenPath(map, detour);
  EXPECT_TRUE(pathFree(map, taut));
  EXPECT_EQ(test::findCollision(grid, taut), "");
  // Optimal: (5.5, 20.5) -> (15, 15) -> (25, 15) -> (34.5, 20.5).
  const double optimum = 2 * std::hypot(9.5, 5.5) + 10;
  EXPECT_LT(pathLength(taut), optimum * 1.005);
  EXPECT_GE(pathLength(taut), optimum - 1e-6);
  EXPECT_LE(taut.size(), 6u);
}

}  // namespace
}  // namespace beft::planners

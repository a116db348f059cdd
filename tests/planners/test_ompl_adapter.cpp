// The potential-field planner as an ompl::base::Planner: OMPL's SimpleSetup
// and benchmark tooling run it beside OMPL's own planners.
#include "planners/ompl_potential_field.hpp"
#include "planners/ompl_space.hpp"
#include "tests/planners/planner_test_support.hpp"
#include "planners/synthetic_maps.hpp"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace beft::planners {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

struct Fixture {
  std::shared_ptr<PlanningMap> map;
  ob::SpaceInformationPtr si;
  std::unique_ptr<og::SimpleSetup> setup;
};

Fixture uTrapSetup() {
  ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
  const SyntheticCase trap = uTrapCase();
  Fixture f;
  f.map = std::make_shared<PlanningMap>(trap.map, 0.0);
  f.si = makeSpaceInformation(f.map);
  f.setup = std::make_unique<og::SimpleSetup>(f.si);
  ob::ScopedState<> start(f.si), goal(f.si);
  setState(start.get(), trap.queries[0].first);
  setState(goal.get(), trap.queries[0].second);
  f.setup->setStartAndGoalStates(start, goal, 1e-6);
  f.setup->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(f.si));
  return f;
}

TEST(OmplAdapter, SimpleSetupSolvesWithThePotentialFieldPlanner) {
  Fixture f = uTrapSetup();
  PotentialFieldParams params;
  params.target = TargetPotential::Geodesic;
  auto planner = std::make_shared<PotentialFieldOmplPlanner>(f.si, f.map, params);
  EXPECT_EQ(planner->getName(), "PotentialFieldGeodesic");
  EXPECT_TRUE(planner->params().hasParam("particles"));
  f.setup->setPlanner(planner);
  const ob::PlannerStatus status = f.setup->solve(5.0);
  ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION);
  og::PathGeometric& path = f.setup->getSolutionPath();
  EXPECT_TRUE(path.check());  // OMPL's own validity check of every state and motion
  Path points;
  for (const ob::State* s : path.getStates()) points.push_back(toPoint(s));
  EXPECT_EQ(test::findCollision(f.map->inflated(), points), "");
  EXPECT_NEAR(points.back().x, 56.5, 1e-9);
}

TEST(OmplAdapter, EveryDeclaredParameterIsInOmplsParamSetWithItsRange) {
  Fixture f = uTrapSetup();
  auto planner = std::make_shared<PotentialFieldOmplPlanner>(f.si, f.map, PotentialFieldParams{});
  PotentialFieldParams defaults;
  DeclaredParameters declared;
  defaults.declare(declared);
  for (const auto& info : declared.list()) {
    ASSERT_TRUE(planner->params().hasParam(info.name)) << info.name;
    EXPECT_EQ(planner->params().getParam(info.name)->getValue(), info.default_value) << info.name;
  }
  EXPECT_TRUE(planner->params().setParam("straightness_weight", "0.5"));
  EXPECT_EQ(planner->params().getParam("straightness_weight")->getValue(), "0.5");
  EXPECT_FALSE(planner->params().setParam("step", "3")) << "outside (0, 1]";
  EXPECT_EQ(planner->params().getParam("step")->getValue(), "1");
}

TEST(OmplAdapter, AMotionIntoAWallIsInvalidAndStopsBeforeIt) {
  Fixture f = uTrapSetup();
  ob::ScopedState<> a(f.si), b(f.si), last(f.si);
  setState(a.get(), {30.5, 32.5});
  setState(b.get(), {50.5, 32.5});  // through the U's bottom (x 38..41)
  EXPECT_FALSE(f.si->checkMotion(a.get(), b.get()));
  std::pair<ob::State*, double> last_valid(last.get(), 0.0);
  EXPECT_FALSE(f.si->getMotionValidator()->checkMotion(a.get(), b.get(), last_valid));
  EXPECT_LT(toPoint(last.get()).x, 38.0);
  EXPECT_GT(toPoint(last.get()).x, 37.0);
}

TEST(OmplAdapter, OmplBenchmarkRunsItBesideRrtConnectAndWritesTheLog) {
  Fixture f = uTrapSetup();
  ompl::tools::Benchmark benchmark(*f.setup, "u-trap");
  benchmark.addPlanner(std::make_shared<PotentialFieldOmplPlanner>(f.si, f.map));
  benchmark.addPlanner(std::make_shared<og::RRTConnect>(f.si));
  ompl::tools::Benchmark::Request request(1.0, 1024.0, 2);
  request.displayProgress = false;
  request.saveConsoleOutput = false;
  benchmark.benchmark(request);
  const auto& results = benchmark.getRecordedExperimentData();
  ASSERT_EQ(results.planners.size(), 2u);
  EXPECT_EQ(results.planners[0].name, "geometric_PotentialField");
  ASSERT_EQ(results.planners[0].runs.size(), 2u);
  EXPECT_EQ(results.planners[0].runs[0].at("solved BOOLEAN"), "1");
  const std::string file =
      (std::filesystem::temp_directory_path() / ("beft_ompl_" + std::to_string(getpid()) + ".log")).string();
  ASSERT_TRUE(benchmark.saveResultsToFile(file.c_str()));
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  std::filesystem::remove(file);
  EXPECT_NE(text.str().find("geometric_PotentialField"), std::string::npos);
  EXPECT_NE(text.str().find("geometric_RRTConnect"), std::string::npos);
}

}  // namespace
}  // namespace beft::planners

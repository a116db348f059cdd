// The paper's figures: Fig. 3 with its planner as printed, Fig. 4 from a
// fresh fig4_dw run.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <string>

#include "tools/figure/figure3.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "tests/system/run_support.hpp"
#include "tools/figure/scene_grid.hpp"

namespace {

using namespace beft;

const std::string kYard = std::string(BEFT_SOURCE_DIR) + "/scenarios/yard.xml";

TEST(SceneGrid, WallsAndCarsAreObstaclesPersonsAreNot) {
  const auto scene = scenario::loadScenario(kYard);
  const auto grid = figure::groundTruthGrid(scene);
  EXPECT_EQ(grid.width(), 300);
  EXPECT_EQ(grid.height(), 200);
  EXPECT_TRUE(grid.blocked(50, 100));   // building_wall at (5, 10)
  EXPECT_TRUE(grid.blocked(120, 150));  // car1 at (12, 15)
  EXPECT_FALSE(grid.blocked(90, 40));   // victim_seen at (9, 4): a person
  EXPECT_FALSE(grid.blocked(20, 20));   // the robot's start
}

TEST(Figure3, ThreePathsOfThePapersPlannerEachTheWinningParticlesOwn) {
  const std::string dir = system_test::makeTempDir("figure3");
  figure::Figure3Options options;
  options.scenario_path = kYard;
  options.starts = {{2, 2}, {3, 17}, {27, 2}};
  options.goal = {26, 10};
  options.out = dir + "/fig3.png";
  const auto result = figure::drawFigure3(options);
  ASSERT_EQ(result.lengths_m.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const double straight = std::hypot(options.goal.x - options.starts[i].x, options.goal.y - options.starts[i].y);
    EXPECT_GE(result.lengths_m[i], straight - 1e-9);
    EXPECT_GT(result.arrived[i], 0);
    // h_W itself, not shortened: about a waypoint per 0.1 m cell travelled.
    EXPECT_GE(static_cast<double>(result.waypoints[i]), 0.8 * result.lengths_m[i] / 0.1) << i;
  }
  const cv::Mat picture = cv::imread(options.out);
  ASSERT_FALSE(picture.empty());
  EXPECT_EQ(picture.cols * 2, picture.rows * 3);  // the yard's 30 x 20 m
  // Seeded: the same figure twice.
  EXPECT_EQ(figure::drawFigure3(options).lengths_m, result.lengths_m);
}

TEST(FigureProgram, Figure3AndFigure4AreOneCommandEach) {
  const std::string dir = system_test::makeTempDir("figure_program");
  const auto three = system_test::runCommand(system_test::binDir() + "/beft-figure 3 --out " + dir + "/fig3.png", 120);
  ASSERT_EQ(three.exit_code, 0) << three.output;
  EXPECT_NE(three.output.find("from (2.0, 2.0): "), std::string::npos) << three.output;
  const auto four = system_test::runCommand(system_test::binDir() + "/beft-figure 4 --out " + dir + "/fig4.png", 500);
  ASSERT_EQ(four.exit_code, 0) << four.output;
  const cv::Mat weights = cv::imread(dir + "/fig4.png");
  EXPECT_GT(weights.cols, 800);
  EXPECT_GT(weights.rows, 600);
  const auto bad = system_test::runCommand(system_test::binDir() + "/beft-figure 3 --out " + dir + "/x.png --start 5", 60);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("--start '5' is not X,Y"), std::string::npos) << bad.output;
}

}  // namespace

#include "planners/bench/bench_datasets.hpp"
#include "planners/bench/bench_report.hpp"
#include "planners/bench/bench_stats.hpp"
#include "planners/bench/scenario_raster.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <unistd.h>

namespace beft::planners::bench {
namespace {

TEST(BenchStats, PercentilesInterpolateAndKeepInfinity) {
  EXPECT_DOUBLE_EQ(median({3, 1, 2}), 2.0);
  EXPECT_DOUBLE_EQ(median({4, 1, 2, 3}), 2.5);
  EXPECT_DOUBLE_EQ(percentile({0, 10, 20, 30, 40}, 0.25), 10.0);
  EXPECT_DOUBLE_EQ(percentile({0, 10}, 0.75), 7.5);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(std::isinf(median({1, inf, inf})));
  EXPECT_DOUBLE_EQ(median({1, 2, inf}), 2.0);
  EXPECT_TRUE(std::isnan(median({})));
}

TEST(BenchStats, SummariesPerPlannerAndMap) {
  std::vector<RunRecord> runs;
  const auto add = [&](const std::string& planner, const std::string& map, bool success, double ms, double ratio) {
    RunRecord r;
    r.planner = planner;
    r.map = map;
    r.success = success;
    r.time_ms = ms;
    r.ratio = ratio;
    runs.push_back(r);
  };
  add("a", "m1", true, 1, 1.0);
  add("a", "m1", false, 9, 0);
  add("a", "m2", true, 3, 1.2);
  add("b", "m1", true, 5, 0.9);
  const auto per_map = summarize(runs, true);
  ASSERT_EQ(per_map.size(), 3u);
  EXPECT_EQ(per_map[0].planner, "a");
  EXPECT_EQ(per_map[0].map, "m1");
  EXPECT_EQ(per_map[0].runs, 2);
  EXPECT_DOUBLE_EQ(per_map[0].success_rate, 0.5);
  EXPECT_DOUBLE_EQ(per_map[0].ratio_median, 1.0);  // failures carry no length
  EXPECT_DOUBLE_EQ(per_map[0].time_median, 5.0);   // but count in time
  const auto overall = summarize(runs, false);
  ASSERT_EQ(overall.size(), 2u);
  EXPECT_EQ(overall[0].map, "all");
  EXPECT_EQ(overall[0].runs, 3);
  EXPECT_DOUBLE_EQ(overall[0].ratio_median, 1.1);
}

TEST(BenchReport, CsvQuotesFieldsAndWritesEveryRun) {
  EXPECT_EQ(csvField("plain"), "plain");
  EXPECT_EQ(csvField("a,b"), "\"a,b\"");
  EXPECT_EQ(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  RunRecord r;
  r.planner = "pf";
  r.map = "u-trap";
  r.success = true;
  r.ratio = 1.25;
  r.message = "note, with comma";
  const std::string file =
      (std::filesystem::temp_directory_path() / ("beft_runs_" + std::to_string(getpid()) + ".csv")).string();
  writeRunsCsv(file, {r, r});
  std::ifstream in(file);
  std::string header, line;
  std::getline(in, header);
  int lines = 0;
  while (std::getline(in, line)) {
    ++lines;
    EXPECT_NE(line.find("1.25000"), std::string::npos) << line;
    EXPECT_NE(line.find("\"note, with comma\""), std::string::npos) << line;
  }
  std::filesystem::remove(file);
  EXPECT_EQ(lines, 2);
  EXPECT_EQ(header.rfind("planner,dataset,map,query", 0), 0u);
  EXPECT_THROW(writeRunsCsv("/nonexistent-dir/runs.csv", {r}), std::runtime_error);
}

TEST(BenchReport, PlotMarksEachPlannersMedian) {
  std::vector<RunRecord> runs;
  for (int i = 0; i < 5; ++i) {
    RunRecord r;
    r.planner = i < 3 ? "fast" : "slow";
    r.success = true;
    r.time_ms = i < 3 ? 1.0 : 100.0;
    r.ratio = 1.0;
    runs.push_back(r);
  }
  const cv::Mat plot = plotLengthRatioVsTime(runs, {"fast", "slow"}, "test");
  ASSERT_FALSE(plot.empty());
  // Something other than white is drawn where each median lies: the plot
  // area's left third (1 ms) and right third (100 ms) on the optimum line.
  const auto drawn = [&plot](int x0, int x1) {
    int count = 0;
    for (int y = 50; y < plot.rows - 70; ++y) {
      for (int x = x0; x < x1; ++x) count += plot.at<cv::Vec3b>(y, x) != cv::Vec3b(255, 255, 255);
    }
    return count;
  };
  EXPECT_GT(drawn(100, 400), 50);
  EXPECT_GT(drawn(500, 830), 50);
}

TEST(BenchDatasets, SpreadIndicesCoverTheRange) {
  EXPECT_EQ(spreadIndices(10, 3), (std::vector<size_t>{0, 4, 9}));
  EXPECT_EQ(spreadIndices(3, 5), (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(spreadIndices(9, 1), (std::vector<size_t>{4}));
  EXPECT_TRUE(spreadIndices(0, 3).empty());
}

TEST(BenchDatasets, TrapMapsCarryTheirOctileOptima) {
  const auto maps = trapMaps();
  ASSERT_EQ(maps.size(), 3u);
  for (const auto& m : maps) {
    ASSERT_FALSE(m.queries.empty());
    for (const auto& q : m.queries) EXPECT_GT(q.optimum, distance(q.start, q.goal) - 1e-9) << m.name;
  }
}

TEST(ScenarioRaster, BoxesAndCylindersBecomeOccupiedCells) {
  beft::scenario::Scenario s;
  s.name = "raster";
  s.world.width = 4.0;
  s.world.height = 3.0;
  s.world.resolution = 0.1;
  s.robot.x = 0.5;
  s.robot.y = 0.5;
  beft::scenario::Object wall;
  wall.id = "wall";
  wall.x = 2.0;
  wall.y = 1.5;
  wall.yaw = 90;  // its 2 m length along y
  wall.visual = beft::scenario::Visual{};
  wall.visual->size_x = 2.0;
  wall.visual->size_y = 0.2;
  wall.visual->size_z = 2.0;
  beft::scenario::Object person;
  person.id = "p";
  person.x = 3.5;
  person.y = 2.5;
  person.visual = beft::scenario::Visual{};
  person.visual->shape = beft::scenario::Visual::Shape::Cylinder;
  person.visual->radius = 0.3;
  beft::scenario::Object voice;  // no visual: not an obstacle
  voice.id = "voice";
  voice.x = 1.0;
  voice.y = 2.5;
  s.objects = {wall, person, voice};
  const ScenarioMap map = rasterizeScenario(s);
  EXPECT_EQ(map.grid.width(), 40);
  EXPECT_EQ(map.grid.height(), 30);
  EXPECT_DOUBLE_EQ(map.robot_radius, 3.5);
  EXPECT_DOUBLE_EQ(map.robot_start.x, 5.0);
  EXPECT_TRUE(map.grid.blocked(20, 15));   // wall centre
  EXPECT_TRUE(map.grid.blocked(20, 6));    // wall, 0.95 m from its centre
  EXPECT_FALSE(map.grid.blocked(20, 28));  // beyond its end
  EXPECT_FALSE(map.grid.blocked(23, 15));  // beside it
  EXPECT_TRUE(map.grid.blocked(35, 25));   // the person
  EXPECT_FALSE(map.grid.blocked(10, 25));  // the invisible voice
}

}  // namespace
}  // namespace beft::planners::bench

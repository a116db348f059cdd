// beft-plan as users run it: JSON output on a MovingAI map, and clear errors
// with a non-zero exit for bad input.
#include "planners/movingai.hpp"
#include "tests/planners/planner_test_support.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace beft::planners {
namespace {

struct Output {
  int status = -1;
  std::string text;  // stdout and stderr
};

Output runPlan(const std::string& args) {
  Output out;
  const std::string command = std::string(BEFT_PLAN_BINARY) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) out.text.append(buffer.data(), n);
  const int status = pclose(pipe);
  out.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

std::string mapFile() { return test::movingAiFile("random-32-32-20.map"); }

TEST(PlanCli, PrintsOneJsonObjectWithAFreePath) {
  const auto queries = loadMovingAiScenario(mapFile() + ".scen");
  const MovingAiQuery& q = queries.back();
  const std::string png = (std::filesystem::temp_directory_path() / ("beft_plan_" + std::to_string(getpid()) + ".png")).string();
  for (const std::string planner : {"astar", "pf-geodesic"}) {
    const Output out = runPlan(mapFile() + " " + std::to_string(q.start_x) + " " + std::to_string(q.start_y) + " " +
                               std::to_string(q.goal_x) + " " + std::to_string(q.goal_y) + " --planner " + planner +
                               " --json --png " + png);
    ASSERT_EQ(out.status, 0) << out.text;
    const auto json = nlohmann::json::parse(out.text);
    EXPECT_EQ(json["planner"], planner);
    EXPECT_TRUE(json["success"].get<bool>());
    EXPECT_GT(json["time_ms"].get<double>(), 0.0);
    const double length = json["length"];
    EXPECT_LE(length, q.optimal_length + 1e-6);  // taut, so no longer than the octile optimum
    EXPECT_GE(length, q.optimal_length / 1.42);
    const auto& path = json["path"];
    ASSERT_GE(path.size(), 2u);
    EXPECT_DOUBLE_EQ(path.front()[0].get<double>(), q.start_x);  // cell coordinates as given
    EXPECT_DOUBLE_EQ(path.back()[1].get<double>(), q.goal_y);
    Path cells;
    for (const auto& p : path) cells.push_back({p[0].get<double>() + 0.5, p[1].get<double>() + 0.5});
    EXPECT_EQ(test::findCollision(loadMovingAiMap(mapFile()), cells), "");
    EXPECT_GT(std::filesystem::file_size(png), 1000u);
    std::filesystem::remove(png);
  }
}

TEST(PlanCli, BadInputGetsAClearErrorAndExitStatus2) {
  const GridMap grid = loadMovingAiMap(mapFile());
  int bx = -1, by = -1;
  for (int y = 0; y < grid.height() && bx < 0; ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      if (grid.blocked(x, y)) { bx = x; by = y; break; }
    }
  }
  ASSERT_GE(bx, 0);
  int fx = -1, fy = -1;
  for (int y = 0; y < grid.height() && fx < 0; ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      if (!grid.blocked(x, y)) { fx = x; fy = y; break; }
    }
  }
  const std::string free_cell = std::to_string(fx) + " " + std::to_string(fy);
  Output out = runPlan("/nonexistent/none.map 1 1 2 2");
  EXPECT_EQ(out.status, 2);
  EXPECT_NE(out.text.find("none.map: cannot open the map file"), std::string::npos) << out.text;
  out = runPlan(mapFile() + " " + std::to_string(bx) + " " + std::to_string(by) + " " + free_cell);
  EXPECT_EQ(out.status, 2);
  EXPECT_NE(out.text.find("is an obstacle cell"), std::string::npos) << out.text;
  out = runPlan(mapFile() + " " + free_cell + " 40 3");
  EXPECT_EQ(out.status, 2);
  EXPECT_NE(out.text.find("goal (40, 3) is outside the 32 x 32 map"), std::string::npos) << out.text;
  out = runPlan(mapFile() + " " + free_cell + " " + free_cell + " --planner dijkstra");
  EXPECT_EQ(out.status, 2);
  EXPECT_NE(out.text.find("unknown planner 'dijkstra'"), std::string::npos) << out.text;
}

TEST(PlanCli, NoPathIsExitStatus1WithTheReason) {
  // A map cut in two: the goal exists but cannot be reached.
  const std::string file = (std::filesystem::temp_directory_path() / ("beft_cut_" + std::to_string(getpid()) + ".map")).string();
  FILE* f = std::fopen(file.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs("type octile\nheight 3\nwidth 5\nmap\n..@..\n..@..\n..@..\n", f);
  std::fclose(f);
  const Output out = runPlan(file + " 0 1 4 1 --planner astar");
  std::filesystem::remove(file);
  EXPECT_EQ(out.status, 1) << out.text;
  EXPECT_NE(out.text.find("success    no"), std::string::npos) << out.text;
  EXPECT_NE(out.text.find("unreachable"), std::string::npos) << out.text;
}

}  // namespace
}  // namespace beft::planners

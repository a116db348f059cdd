#include "planners/astar_planner.hpp"
#include "planners/movingai.hpp"
#include "planners/octile_search.hpp"
#include "tests/planners/planner_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <cmath>
#include <limits>
#include <queue>
#include <random>

#include <unistd.h>

namespace beft::planners {
namespace {

namespace fs = std::filesystem;

// Every map kept in the repository, by name: a missing one fails the test.
const char* const kMovingAiMaps[] = {"AcrosstheCape.map", "Berlin_0_256.map",  "Boston_2_512.map",
                                     "Denver_1_256.map",  "NewYork_1_512.map", "arena.map",
                                     "maze512-32-9.map",  "random-32-32-20.map", "rmtst01.map"};

// About `count` queries spread evenly over the file (it is sorted by bucket).
std::vector<MovingAiQuery> stratified(const std::vector<MovingAiQuery>& all, size_t count) {
  std::vector<MovingAiQuery> out;
  for (size_t i = 0; i < count && !all.empty(); ++i) out.push_back(all[i * (all.size() - 1) / std::max<size_t>(1, count - 1)]);
  return out;
}

TEST(MovingAi, AStarReproducesTheScenarioOptimaOnEveryMap) {
  int checked = 0;
  for (const char* name : kMovingAiMaps) {
    const std::string map_file = test::movingAiFile(name);
    SCOPED_TRACE(map_file);
    const GridMap grid = loadMovingAiMap(map_file);
    const auto queries = loadMovingAiScenario(map_file + ".scen");
    ASSERT_FALSE(queries.empty());
    for (const MovingAiQuery& q : stratified(queries, 12)) {
      SCOPED_TRACE("scenario line " + std::to_string(q.line));
      ASSERT_EQ(q.map_width, grid.width());
      ASSERT_EQ(q.map_height, grid.height());
      const auto result = octileAStar(grid, {q.start_x, q.start_y}, {q.goal_x, q.goal_y});
      if (!q.reachable()) {
        EXPECT_FALSE(result.found);
        continue;
      }
      ASSERT_TRUE(result.found);
      // The files print 6 significant digits (e.g. 1176.61).
      EXPECT_NEAR(result.cost, q.optimal_length, 1e-4 + 5e-6 * q.optimal_length);
      // The cell path is a chain of allowed moves whose length is the cost.
      Path centres;
      for (const GridCell& c : result.cells) centres.push_back(cellCentre(c.x, c.y));
      EXPECT_NEAR(pathLength(centres), result.cost, 1e-6);
      EXPECT_EQ(test::findCollision(grid, centres), "");
      ++checked;
    }
  }
  EXPECT_GE(checked, 90);
}

TEST(MovingAi, AStarPlannerReportsTheOptimumAndAFreeSparsePath) {
  const std::string map_file = test::movingAiFile("random-32-32-20.map");
  auto map = std::make_shared<PlanningMap>(loadMovingAiMap(map_file), 0.0);
  const auto queries = loadMovingAiScenario(map_file + ".scen");
  AStarPlanner planner;
  planner.setup(map);
  for (const MovingAiQuery& q : stratified(queries, 10)) {
    const PlanResult r = planner.solve(cellCentre(q.start_x, q.start_y), cellCentre(q.goal_x, q.goal_y),
                                       Deadline::after(5));
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_NEAR(planner.statistics().at("octile_cost"), q.optimal_length, 1e-4);
    EXPECT_NEAR(pathLength(r.raw_path), q.optimal_length, 1e-4);
    EXPECT_LE(r.length(), q.optimal_length + 1e-9);  // shortcutting never lengthens
    EXPECT_EQ(test::findCollision(map->inflated(), r.path), "");
  }
}

TEST(OctileSearch, DistanceFieldEqualsAStarCosts) {
  std::mt19937 rng(5);
  GridMap grid(60, 45);
  for (int i = 0; i < 700; ++i) grid.setBlocked(rng() % 60, rng() % 45);
  const GridCell goal{30, 20};
  grid.setBlocked(goal.x, goal.y, false);
  const auto field = octileDistanceField(grid, goal);
  int reachable = 0;
  for (int y = 0; y < 45; y += 2) {
    for (int x = 0; x < 60; x += 3) {
      if (grid.blocked(x, y)) {
        EXPECT_TRUE(std::isinf(field[grid.index(x, y)]));
        continue;
      }
      const auto path = octileAStar(grid, {x, y}, goal);
      if (!path.found) {
        EXPECT_TRUE(std::isinf(field[grid.index(x, y)]));
        continue;
      }
      ++reachable;
      EXPECT_NEAR(field[grid.index(x, y)], path.cost, 1e-9) << x << "," << y;
    }
  }
  EXPECT_GT(reachable, 250);
}

// Plain Dijkstra over the same moves (a diagonal only between two free
// cells), the reference for the wavefront.
std::vector<double> referenceField(const GridMap& grid, GridCell goal) {
  const int w = grid.width();
  std::vector<double> dist(static_cast<size_t>(w) * grid.height(), std::numeric_limits<double>::infinity());
  if (grid.blocked(goal.x, goal.y)) return dist;
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  dist[grid.index(goal.x, goal.y)] = 0;
  open.push({0.0, static_cast<int>(grid.index(goal.x, goal.y))});
  while (!open.empty()) {
    const auto [d, index] = open.top();
    open.pop();
    if (d > dist[index]) continue;
    const int x = index % w, y = index / w;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || grid.blocked(x + dx, y + dy)) continue;
        if (dx != 0 && dy != 0 && (grid.blocked(x + dx, y) || grid.blocked(x, y + dy))) continue;
        const double cost = d + (dx != 0 && dy != 0 ? std::sqrt(2.0) : 1.0);
        const size_t next = grid.index(x + dx, y + dy);
        if (cost < dist[next]) {
          dist[next] = cost;
          open.push({cost, static_cast<int>(next)});
        }
      }
  }
  return dist;
}

TEST(OctileSearch, DistanceFieldMatchesDijkstraUpToTheGridsEdges) {
  std::mt19937 rng(11);
  const std::pair<int, int> sizes[] = {{1, 1}, {1, 9}, {9, 1}, {2, 2}, {17, 5}, {40, 33}, {64, 64}};
  int compared = 0;
  for (const auto& [w, h] : sizes) {
    for (int trial = 0; trial < 6; ++trial) {
      GridMap grid(w, h);
      const int obstacles = (w * h) / 4;
      for (int i = 0; i < obstacles; ++i) grid.setBlocked(rng() % w, rng() % h);
      // Goals on corners and edges too: the field must neither wrap around nor leave the grid.
      const GridCell goal{trial % 2 == 0 ? 0 : static_cast<int>(rng() % w), trial % 3 == 0 ? h - 1 : static_cast<int>(rng() % h)};
      grid.setBlocked(goal.x, goal.y, false);
      const auto field = octileDistanceField(grid, goal);
      const auto reference = referenceField(grid, goal);
      ASSERT_EQ(field.size(), reference.size());
      for (size_t i = 0; i < field.size(); ++i) {
        if (std::isinf(reference[i])) {
          EXPECT_TRUE(std::isinf(field[i])) << w << "x" << h << " cell " << i;
        } else {
          EXPECT_NEAR(field[i], reference[i], 1e-9) << w << "x" << h << " cell " << i;
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 5000);
}

TEST(OctileSearch, BoundedFieldIsTheFullFieldWithinItsLimit) {
  std::mt19937 rng(3);
  GridMap grid(80, 50);
  for (int i = 0; i < 900; ++i) grid.setBlocked(rng() % 80, rng() % 50);
  const GridCell goal{70, 40}, start{5, 6};
  grid.setBlocked(goal.x, goal.y, false);
  grid.setBlocked(start.x, start.y, false);
  const auto full = octileDistanceField(grid, goal);
  const double to_start = full[grid.index(start.x, start.y)];
  ASSERT_TRUE(std::isfinite(to_start));
  const double slack = 1.2, margin = 5.0;
  const auto bounded = octileDistanceField(grid, goal, start, slack, margin);
  int beyond = 0;
  for (size_t i = 0; i < full.size(); ++i) {
    if (full[i] <= slack * to_start + margin) {
      EXPECT_EQ(bounded[i], full[i]) << "cell " << i;
    } else if (std::isinf(bounded[i])) {
      ++beyond;
    } else {
      EXPECT_EQ(bounded[i], full[i]) << "cell " << i;  // a finished bucket beyond the limit is still exact
    }
  }
  EXPECT_GT(beyond, 0) << "the bound cut nothing off";
}

// Grown in steps, in a window that starts small and widens, or over the
// whole grid at once: the same cells final, with the same values.
TEST(OctileWavefront, GrownBucketByBucketFinishesCellsInOrderOfDistance) {
  std::mt19937 rng(11);
  GridMap grid(90, 60);
  for (int i = 0; i < 1500; ++i) grid.setBlocked(rng() % 90, rng() % 60);
  const GridCell goal{20, 30};
  grid.setBlocked(goal.x, goal.y, false);
  const auto full = octileDistanceField(grid, goal);
  for (const int reach : {std::numeric_limits<int>::max(), 2, 9}) {
    OctileWavefront wavefront(grid, goal, reach);
    int checked_final = 0;
    for (int64_t bucket = 0; !wavefront.exhausted(); bucket += 7) {
      wavefront.growThroughBucket(bucket);
      for (int y = 0; y < grid.height(); ++y)
        for (int x = 0; x < grid.width(); ++x) {
          const double expected = full[grid.index(x, y)];
          if (wavefront.exhausted()) {
            ASSERT_EQ(wavefront.value(x, y), expected);
          } else if (expected < bucket + 1) {
            ASSERT_TRUE(wavefront.isFinal(x, y)) << x << "," << y << " at bucket " << bucket << ", reach " << reach;
            ASSERT_EQ(wavefront.value(x, y), expected);
            ++checked_final;
          } else {
            ASSERT_FALSE(wavefront.isFinal(x, y)) << x << "," << y << " at bucket " << bucket << ", reach " << reach;
          }
        }
    }
    EXPECT_GT(checked_final, 10000);
    // Grown until one cell is final: that cell's distance is the full field's.
    OctileWavefront to_one(grid, goal, reach);
    to_one.growUntilFinal({85, 5});
    EXPECT_TRUE(to_one.isFinal(85, 5));
    EXPECT_EQ(to_one.value(85, 5), full[grid.index(85, 5)]);
    // Bounded around a start, in a small window or not: the bounded field.
    OctileWavefront around(grid, goal, reach);
    around.growAround({70, 10}, 1.2, 5.0);
    EXPECT_EQ(around.values(), octileDistanceField(grid, goal, {70, 10}, 1.2, 5.0)) << "reach " << reach;
    // A row's values at once, across the window's and the grid's edges: value() of each cell.
    for (int y = -2; y < grid.height() + 2; y += 3) {
      const int x0 = static_cast<int>(rng() % 100) - 5, x1 = x0 + static_cast<int>(rng() % 100);
      std::vector<double> row(static_cast<size_t>(x1 - x0 + 1), -1.0);
      around.rowValues(y, x0, x1, row.data());
      for (int x = x0; x <= x1; ++x) ASSERT_EQ(row[x - x0], around.value(x, y)) << x << "," << y << ", reach " << reach;
    }
  }
  // A walled-in goal: exhausted inside a small window, everything else unreachable.
  GridMap box(40, 40);
  box.fillRect(10, 10, 20, 10);
  box.fillRect(10, 20, 20, 20);
  box.fillRect(10, 10, 10, 20);
  box.fillRect(20, 10, 20, 20);
  OctileWavefront boxed(box, {15, 15}, 8);
  boxed.growUntilFinal({35, 35});
  EXPECT_TRUE(boxed.exhausted());
  EXPECT_TRUE(boxed.isFinal(35, 35));
  EXPECT_TRUE(std::isinf(boxed.value(35, 35)));
  EXPECT_EQ(boxed.value(12, 12), std::sqrt(2.0) * 3);
}

class MovingAiFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("beft_movingai_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  fs::path dir_;
};

TEST_F(MovingAiFiles, ReadsCrlfMaps) {
  const auto path = write("ok.map", "type octile\r\nheight 2\r\nwidth 3\r\nmap\r\n.@.\r\nTG.\r\n");
  const GridMap grid = loadMovingAiMap(path);
  EXPECT_EQ(grid.width(), 3);
  EXPECT_EQ(grid.height(), 2);
  EXPECT_TRUE(grid.blocked(1, 0));
  EXPECT_TRUE(grid.blocked(0, 1));
  EXPECT_FALSE(grid.blocked(1, 1));
}

TEST_F(MovingAiFiles, RefusesBrokenMapsWithFileAndLine) {
  const auto expect_error = [](const std::string& path, const std::string& fragment) {
    try {
      loadMovingAiMap(path);
      ADD_FAILURE() << "no error for " << path;
    } catch (const MapFormatError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expect_error((dir_ / "missing.map").string(), "cannot open");
  expect_error(write("a.map", "hello\n"), "a.map:1: expected 'type octile'");
  expect_error(write("b.map", "type octile\nheight x\nwidth 3\nmap\n"), "b.map:2: expected 'height N'");
  expect_error(write("c.map", "type octile\nheight 2\nwidth 3\nmap\n...\n..\n"), "c.map:6: row has 2 cells");
  expect_error(write("d.map", "type octile\nheight 2\nwidth 3\nmap\n...\n.x.\n"), "d.map:6: unknown cell character 'x'");
  expect_error(write("e.map", "type octile\nheight 3\nwidth 3\nmap\n...\n...\n"), "e.map:7: the map ends after 2 of the 3 rows");
}

TEST_F(MovingAiFiles, RefusesBrokenScenarios) {
  const auto path = write("x.map.scen", "version 1\n0\tx.map\t3\t2\t0\t0\t2\t1\t2.41\n0\tx.map\t3\t2\t0\t0\n");
  try {
    loadMovingAiScenario(path);
    ADD_FAILURE() << "no error";
  } catch (const MapFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("x.map.scen:3: expected 9 fields"), std::string::npos) << e.what();
  }
  const auto outside = write("y.map.scen", "version 1\n0\ty.map\t3\t2\t0\t0\t5\t1\t2.41\n");
  EXPECT_THROW(loadMovingAiScenario(outside), MapFormatError);
}

}  // namespace
}  // namespace beft::planners

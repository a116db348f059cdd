#include "planners/path_tools.hpp"
#include "tests/planners/planner_test_support.hpp"
#include "planners/planning_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace beft::planners {
namespace {

TEST(Inflation, ZeroRadiusKeepsTheMap) {
  GridMap grid(10, 10);
  grid.setBlocked(4, 4);
  const GridMap out = inflate(grid, 0.0);
  EXPECT_EQ(out.cells(), grid.cells());
}

TEST(Inflation, GrowsByTheSquareToSquareDistance) {
  GridMap grid(21, 21);
  grid.setBlocked(10, 10);
  const GridMap out = inflate(grid, 1.5);
  // Offsets (dx, dy) are blocked when hypot(max(|dx|-1,0), max(|dy|-1,0)) < 1.5.
  for (int y = 0; y < 21; ++y) {
    for (int x = 0; x < 21; ++x) {
      const int dx = std::abs(x - 10), dy = std::abs(y - 10);
      const double gap = std::hypot(std::max(dx - 1, 0), std::max(dy - 1, 0));
      EXPECT_EQ(out.blocked(x, y), (dx == 0 && dy == 0) || gap < 1.5) << x << "," << y;
    }
  }
  EXPECT_TRUE(out.blocked(12, 10));   // gap 1
  EXPECT_FALSE(out.blocked(13, 10));  // gap 2
  EXPECT_TRUE(out.blocked(12, 12));   // gap hypot(1, 1) = 1.41
  EXPECT_FALSE(out.blocked(13, 12));  // gap hypot(2, 1)
}

TEST(Inflation, AnyPointOfAFreeCellClearsObstaclesByTheRadius) {
  std::mt19937 rng(3);
  GridMap grid(30, 30);
  for (int i = 0; i < 25; ++i) grid.setBlocked(rng() % 30, rng() % 30);
  const double radius = 2.3;
  const PlanningMap map(grid, radius);
  std::uniform_real_distribution<double> coord(0.0, 30.0);
  int free_points = 0;
  for (int i = 0; i < 4000; ++i) {
    const Point2 p{coord(rng), coord(rng)};
    if (!map.pointFree(p)) continue;
    ++free_points;
    for (int y = 0; y < 30; ++y) {
      for (int x = 0; x < 30; ++x) {
        if (!grid.blocked(x, y)) continue;
        const double dx = std::max({x - p.x, 0.0, p.x - (x + 1)});
        const double dy = std::max({y - p.y, 0.0, p.y - (y + 1)});
        ASSERT_GE(std::hypot(dx, dy), radius) << "point " << p.x << "," << p.y << " cell " << x << "," << y;
      }
    }
  }
  EXPECT_GT(free_points, 200);
}

// Inflated from an earlier map, only around what changed: the same cells as
// inflating the whole map, whatever changed (cells added and removed, near the
// edges, in one place or spread out, nothing) and for radii of every size.
TEST(Inflation, FromAnEarlierMapEqualsInflatingTheWholeMap) {
  std::mt19937 random(21);
  for (int trial = 0; trial < 200; ++trial) {
    std::uniform_int_distribution<int> side(1, 90);
    const int width = side(random), height = side(random);
    std::uniform_int_distribution<int> x_of(0, width - 1), y_of(0, height - 1);
    GridMap earlier(width, height);
    for (int n = std::uniform_int_distribution<int>(0, width * height / 8)(random); n > 0; --n)
      earlier.setBlocked(x_of(random), y_of(random));
    const double radius = std::uniform_real_distribution<double>(0.0, 6.0)(random);
    const GridMap earlier_inflated = inflate(earlier, radius);
    GridMap map = earlier;
    const int changes = std::uniform_int_distribution<int>(0, 12)(random);
    const bool clustered = trial % 2 == 0;
    const int cx = x_of(random), cy = y_of(random);
    for (int n = 0; n < changes; ++n) {
      int x = x_of(random), y = y_of(random);
      if (clustered) {
        x = std::clamp(cx + std::uniform_int_distribution<int>(-3, 3)(random), 0, width - 1);
        y = std::clamp(cy + std::uniform_int_distribution<int>(-3, 3)(random), 0, height - 1);
      }
      map.setBlocked(x, y, !map.blocked(x, y));
    }
    ASSERT_EQ(inflate(map, radius, earlier, earlier_inflated).cells(), inflate(map, radius).cells())
        << "trial " << trial << ": " << width << " x " << height << ", radius " << radius << ", " << changes
        << " changes";
  }
  // An earlier map of another size is not used.
  GridMap small(5, 5), large(8, 8);
  large.setBlocked(7, 7);
  EXPECT_EQ(inflate(large, 1.5, small, inflate(small, 1.5)).cells(), inflate(large, 1.5).cells());
}

TEST(ValidityChecker, DiagonalThroughACornerNeedsBothSideCells) {
  GridMap grid(4, 4);
  grid.setBlocked(2, 1);
  const PlanningMap map(grid, 0);
  // (1,1) -> (2,2) centre to centre passes the corner (2,2) shared with (2,1).
  EXPECT_FALSE(map.segmentFree(cellCentre(1, 1), cellCentre(2, 2)));
  EXPECT_TRUE(map.segmentFree(cellCentre(1, 2), cellCentre(2, 3)));
  EXPECT_TRUE(map.segmentFree(cellCentre(0, 0), cellCentre(3, 0)));
  EXPECT_FALSE(map.segmentFree(cellCentre(0, 1), cellCentre(3, 1)));
}

TEST(ValidityChecker, OutsideTheMapIsBlocked) {
  const PlanningMap map(GridMap(5, 5), 0);
  EXPECT_TRUE(map.pointFree({0.5, 0.5}));
  EXPECT_FALSE(map.pointFree({-0.2, 0.5}));
  EXPECT_FALSE(map.pointFree({5.0, 2.5}));  // on the outer edge
  EXPECT_FALSE(map.segmentFree({0.5, 0.5}, {7.5, 0.5}));
  EXPECT_FALSE(map.segmentFree({0.5, 0.5}, {NAN, 0.5}));
}

TEST(ValidityChecker, AgreesWithTheCellByCellCheckOnRandomSegments) {
  std::mt19937 rng(11);
  GridMap grid(25, 25);
  for (int i = 0; i < 80; ++i) grid.setBlocked(rng() % 25, rng() % 25);
  const PlanningMap map(grid, 0);
  std::uniform_real_distribution<double> coord(0.0, 25.0);
  int free_count = 0;
  for (int i = 0; i < 3000; ++i) {
    const Point2 a{coord(rng), coord(rng)}, b{coord(rng), coord(rng)};
    const bool brute_force_free = test::findCollision(grid, {a, b}).empty();
    EXPECT_EQ(map.segmentFree(a, b), brute_force_free) << a.x << "," << a.y << " -> " << b.x << "," << b.y;
    free_count += brute_force_free;
  }
  EXPECT_GT(free_count, 100);
}

TEST(ValidityChecker, FreeFractionStopsBeforeTheObstacle) {
  GridMap grid(20, 3);
  grid.fillRect(10, 0, 10, 2);
  const PlanningMap map(grid, 0);
  const double t = map.freeFraction({0.5, 1.5}, {19.5, 1.5});
  const double x = 0.5 + t * 19.0;
  EXPECT_LT(x, 10.0);
  EXPECT_GT(x, 9.9);
  EXPECT_DOUBLE_EQ(map.freeFraction({0.5, 1.5}, {5.5, 1.5}), 1.0);
}

TEST(Clearance, DistanceToTheNearestObstacleEdge) {
  GridMap grid(20, 20);
  grid.setBlocked(10, 10);
  const PlanningMap map(grid, 0);
  EXPECT_NEAR(map.clearance(cellCentre(14, 10)), 3.5, 1e-4);
  EXPECT_NEAR(map.clearance(cellCentre(10, 6)), 3.5, 1e-4);
  EXPECT_NEAR(map.clearance({11.2, 11.3}), std::hypot(0.2, 0.3), 1e-9);  // off its corner
}

TEST(Clearance, MatchesTheBruteForceDistanceToEveryObstacleCell) {
  std::mt19937 rng(9);
  GridMap grid(40, 30);
  for (int i = 0; i < 60; ++i) grid.setBlocked(rng() % 40, rng() % 30);
  const PlanningMap map(grid, 0);
  std::uniform_real_distribution<double> x(0.0, 40.0), y(0.0, 30.0);
  for (int i = 0; i < 500; ++i) {
    const Point2 p{x(rng), y(rng)};
    double best = 1e9;
    for (int cy = 0; cy < 30; ++cy) {
      for (int cx = 0; cx < 40; ++cx) {
        if (!grid.blocked(cx, cy)) continue;
        best = std::min(best, std::hypot(std::max({cx - p.x, 0.0, p.x - cx - 1}), std::max({cy - p.y, 0.0, p.y - cy - 1})));
      }
    }
    // The labelled transform is a 5x5-mask approximation: allow a small slack far from obstacles.
    EXPECT_NEAR(map.clearance(p), best, best < 2.0 ? 1e-9 : 0.05 * best) << p.x << "," << p.y;
  }
}

TEST(PathTools, ShortcutIsFreeSparseAndNoLonger) {
  GridMap grid(30, 20);
  grid.fillRect(14, 0, 15, 14);
  const PlanningMap map(grid, 0);
  Path staircase;
  for (int x = 2; x <= 12; ++x) staircase.push_back(cellCentre(x, 4 + (x - 2)));
  for (int y = 15; y <= 16; ++y) staircase.push_back(cellCentre(13, y));
  for (int x = 14; x <= 16; ++x) staircase.push_back(cellCentre(x, 16));
  for (int x = 17; x <= 27; ++x) staircase.push_back(cellCentre(x, 16 - (x - 16)));
  ASSERT_TRUE(pathFree(map, staircase));
  const Path sparse = shortcutPath(map, staircase);
  EXPECT_TRUE(pathFree(map, sparse));
  EXPECT_LE(pathLength(sparse), pathLength(staircase) + 1e-9);
  EXPECT_LT(sparse.size(), 6u);
  EXPECT_DOUBLE_EQ(sparse.front().x, staircase.front().x);
  EXPECT_DOUBLE_EQ(sparse.back().y, staircase.back().y);
}

TEST(PathTools, HeadingsFollowTheSegmentsAndEndAtTheGoalHeading) {
  const Path path{{0, 0}, {1, 0}, {1, 1}};
  const auto headings = travelHeadings(path, 3.0);
  ASSERT_EQ(headings.size(), 3u);
  EXPECT_NEAR(headings[0], 0.0, 1e-12);
  EXPECT_NEAR(headings[1], M_PI / 2, 1e-12);
  EXPECT_NEAR(headings[2], 3.0, 1e-12);
  EXPECT_NEAR(totalTurning(path), M_PI / 2, 1e-12);
}

}  // namespace
}  // namespace beft::planners

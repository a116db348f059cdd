// The exploration expert's logic on synthetic maps and hypotheses: viewpoints
// with a line of sight around a wall (never through it), frontiers on a
// half-known map, and the decision sequence from looking around to verifying,
// retrying, giving up and stopping.
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include <beft/obstacle_map_t.hpp>

#include "experts/exploration/close_looks.hpp"
#include "experts/exploration/explorer.hpp"
#include "experts/exploration/frontiers.hpp"
#include "experts/exploration/known_map.hpp"
#include "experts/exploration/viewpoints.hpp"

namespace beft::exploration {
namespace {

constexpr uint8_t kUnknown = obstacle_map_t::CELL_UNKNOWN;
constexpr uint8_t kFree = obstacle_map_t::CELL_FREE;
constexpr uint8_t kOccupied = obstacle_map_t::CELL_OCCUPIED;

// A width_m x height_m world at 0.1 m, every cell `fill`.
planners::ObstacleCells makeCells(double width_m, double height_m, uint8_t fill) {
  planners::ObstacleCells cells;
  cells.resolution = 0.1;
  cells.width = static_cast<int>(std::lround(width_m / cells.resolution));
  cells.height = static_cast<int>(std::lround(height_m / cells.resolution));
  cells.cells.assign(static_cast<size_t>(cells.width) * cells.height, fill);
  return cells;
}

// Sets the cells whose centres lie in [x0, x1] x [y0, y1] (metres).
void fillRect(planners::ObstacleCells& cells, double x0, double y0, double x1, double y1, uint8_t value) {
  for (int y = 0; y < cells.height; ++y)
    for (int x = 0; x < cells.width; ++x) {
      const double cx = (x + 0.5) * cells.resolution, cy = (y + 0.5) * cells.resolution;
      if (cx >= x0 && cx <= x1 && cy >= y0 && cy <= y1) cells.cells[static_cast<size_t>(y) * cells.width + x] = value;
    }
}

// A 20 x 20 m known, free world with a wall from (10, 4) to (10, 16), 0.2 m thick.
// A fire of 0.5 m radius as the map shows it: every 0.1 m cell whose centre
// lies within 0.55 m of (x, y) occupied.
void fillFire(planners::ObstacleCells& cells, double x, double y) {
  for (int cy = 0; cy < cells.height; ++cy)
    for (int cx = 0; cx < cells.width; ++cx)
      if (std::hypot((cx + 0.5) * cells.resolution - x, (cy + 0.5) * cells.resolution - y) <= 0.55)
        cells.cells[static_cast<size_t>(cy) * cells.width + cx] = kOccupied;
}

planners::ObstacleCells wallWorld() {
  auto cells = makeCells(20, 20, kFree);
  fillRect(cells, 9.9, 4.0, 10.1, 16.0, kOccupied);
  return cells;
}

// Does segment p-q cross the axis-aligned rectangle [x0, x1] x [y0, y1]?
bool segmentHitsRect(double px, double py, double qx, double qy, double x0, double y0, double x1, double y1) {
  for (int i = 0; i <= 1000; ++i) {
    const double s = i / 1000.0;
    const double x = px + (qx - px) * s, y = py + (qy - py) * s;
    if (x >= x0 && x <= x1 && y >= y0 && y <= y1) return true;
  }
  return false;
}

TEST(KnownMap, StandableCellsKeepTheRobotClearOfObstaclesAndTheBorder) {
  const KnownMap map(wallWorld(), 0.45);
  Cell cell;
  ASSERT_TRUE(map.cellOf(9.5, 10.0, cell));  // 0.4 m from the wall's face
  EXPECT_FALSE(map.standable(cell.x, cell.y));
  ASSERT_TRUE(map.cellOf(9.2, 10.0, cell));  // 0.7 m from it
  EXPECT_TRUE(map.standable(cell.x, cell.y));
  ASSERT_TRUE(map.cellOf(0.2, 10.0, cell));  // too close to the world's edge
  EXPECT_FALSE(map.standable(cell.x, cell.y));
  EXPECT_EQ(map.at(-1, 0), kOccupied);
}

// A cell asked alone (its neighbourhood) and the whole inflated grid give
// the same answer for every cell of a cluttered map, radii of several sizes.
TEST(KnownMap, StandableAskedCellByCellIsTheInflatedGridsAnswer) {
  auto cells = makeCells(12, 9, kFree);
  uint64_t state = 12345;
  for (auto& cell : cells.cells) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const int roll = static_cast<int>((state >> 33) % 100);
    cell = roll < 3 ? kOccupied : roll < 20 ? kUnknown : kFree;
  }
  for (double radius : {0.0, 0.05, 0.3, 0.45, 0.72}) {
    const KnownMap cell_by_cell(cells, radius);
    const KnownMap whole(cells, radius);
    const planners::GridMap& grid = whole.standing();
    int standable = 0;
    for (int y = -1; y <= cells.height; ++y)
      for (int x = -1; x <= cells.width; ++x) {
        const bool expected = whole.inside(x, y) && !grid.blocked(x, y);
        ASSERT_EQ(cell_by_cell.standable(x, y), expected) << "radius " << radius << " cell " << x << ", " << y;
        ASSERT_EQ(whole.standable(x, y), expected);
        standable += expected;
      }
    EXPECT_GT(standable, 0) << radius;
  }
}

TEST(KnownMap, SightIsBlockedByOccupiedCellsButNotByTheTargetItself) {
  auto cells = wallWorld();
  fillRect(cells, 11.8, 9.8, 12.2, 10.2, kOccupied);  // the target's own footprint
  const KnownMap map(cells, 0.45);
  EXPECT_FALSE(map.sight(5, 10, 12, 10, 0.5).clear);  // through the wall
  EXPECT_TRUE(map.sight(12, 3, 12, 10, 0.5).clear);   // from below, past the wall's end
  EXPECT_FALSE(map.sight(12, 3, 12, 10, 0.0).clear);  // the target blocks itself unless ignored
}

TEST(KnownMap, SightMeasuresItsLengthThroughUnknownCellsAndMissesNoDiagonalCell) {
  auto cells = makeCells(10, 10, kFree);
  fillRect(cells, 4.0, 0.0, 6.0, 10.0, kUnknown);  // a 2 m band of unknown
  const KnownMap map(cells, 0.3);
  const SightLine across = map.sight(1.05, 5.05, 8.05, 5.05, 0.0);
  EXPECT_TRUE(across.clear);
  EXPECT_NEAR(across.unknown_m, 2.0, 1e-6);
  const SightLine slanted = map.sight(1.05, 2.05, 9.05, 8.05, 0.0);  // 3-4-5: 2 m across x is 2.5 m long
  EXPECT_NEAR(slanted.unknown_m, 2.5, 1e-6);

  auto single = makeCells(10, 10, kFree);
  fillRect(single, 5.0, 5.0, 5.1, 5.1, kOccupied);  // one cell, (50, 50)
  const KnownMap dot(single, 0.3);
  EXPECT_FALSE(dot.sight(2.02, 2.0, 8.02, 8.0, 0.0).clear);  // clips that cell's corner
  EXPECT_TRUE(dot.sight(2.0, 2.3, 8.0, 8.3, 0.0).clear);     // passes beside it
}

TEST(Viewpoints, ChoosesALineOfSightAroundTheWallNotThroughIt) {
  const KnownMap map(wallWorld(), 0.45);
  const TravelField travel(map, 5.0, 10.0, 0.6);
  ViewpointParameters parameters;
  const double tx = 12.0, ty = 10.0;  // hidden behind the wall
  const auto viewpoint = chooseViewpoint(map, travel, tx, ty, {}, parameters);
  ASSERT_TRUE(viewpoint.has_value());
  // Not through the wall, at a legal distance, facing the target.
  EXPECT_FALSE(segmentHitsRect(viewpoint->x, viewpoint->y, tx, ty, 9.9, 4.0, 10.1, 16.0))
      << "viewpoint (" << viewpoint->x << ", " << viewpoint->y << ")";
  const double distance = std::hypot(viewpoint->x - tx, viewpoint->y - ty);
  EXPECT_GE(distance, parameters.min_distance_m - 1e-9);
  EXPECT_LE(distance, parameters.max_distance_m + 1e-9);
  EXPECT_NEAR(viewpoint->yaw, bearingDeg(viewpoint->x, viewpoint->y, tx, ty), 1e-9);
  // Points on the robot's side are closer but blocked: the chosen one had to go around.
  EXPECT_GT(viewpoint->travel_m, 6.0);
  EXPECT_FALSE(inLineOfSight(map, 8.0, 10.0, tx, ty, parameters));
  EXPECT_TRUE(inLineOfSight(map, viewpoint->x, viewpoint->y, tx, ty, parameters));
}

TEST(Viewpoints, PrefersTheRobotsOwnSideWhenTheViewIsClear) {
  const KnownMap map(wallWorld(), 0.45);
  const TravelField travel(map, 5.0, 10.0, 0.6);
  const auto viewpoint = chooseViewpoint(map, travel, 7.0, 10.0, {}, ViewpointParameters{});
  ASSERT_TRUE(viewpoint.has_value());
  EXPECT_LT(viewpoint->travel_m, 0.5);  // already in range with a clear view
}

TEST(Viewpoints, TriedViewpointsAreNotTriedAgain) {
  const KnownMap map(wallWorld(), 0.45);
  const TravelField travel(map, 5.0, 10.0, 0.6);
  ViewpointParameters parameters;
  const auto first = chooseViewpoint(map, travel, 12, 10, {}, parameters);
  ASSERT_TRUE(first.has_value());
  const auto second = chooseViewpoint(map, travel, 12, 10, {{first->x, first->y}}, parameters);
  ASSERT_TRUE(second.has_value());
  EXPECT_GE(std::hypot(second->x - first->x, second->y - first->y), parameters.tried_radius_m);
  EXPECT_GE(second->cost, first->cost);
}

TEST(Viewpoints, NoneWhenTheTargetIsWalledIn) {
  auto cells = makeCells(20, 20, kFree);
  fillRect(cells, 9.0, 9.0, 15.0, 9.2, kOccupied);  // a closed box around (12, 10)
  fillRect(cells, 9.0, 10.8, 15.0, 11.0, kOccupied);
  fillRect(cells, 9.0, 9.0, 9.2, 11.0, kOccupied);
  fillRect(cells, 14.8, 9.0, 15.0, 11.0, kOccupied);
  const KnownMap map(cells, 0.45);
  const TravelField travel(map, 3.0, 3.0, 0.6);
  EXPECT_FALSE(chooseViewpoint(map, travel, 12, 10, {}, ViewpointParameters{}).has_value());
}

// A car seen whole fills its footprint on the map: a line of sight that
// reaches its near side reaches the car. A wall beside it, across free
// space, still blocks.
TEST(Viewpoints, ACarsOwnBodyDoesNotHideItButAWallBesideItDoes) {
  auto cells = makeCells(20, 20, kFree);
  fillRect(cells, 9.1, 7.75, 10.9, 12.25, kOccupied);   // a 1.8 x 4.5 m car centred on (10, 10)
  fillRect(cells, 12.0, 6.0, 12.2, 14.0, kOccupied);    // a wall 1.1 m east of its side
  const KnownMap map(cells, 0.45);
  const TravelField travel(map, 3.0, 10.0, 0.6);
  ViewpointParameters person;  // a target no wider than target_clearance_m
  EXPECT_FALSE(chooseViewpoint(map, travel, 10, 10, {}, person).has_value())
      << "the car's own cells hide the car's centre from everywhere";
  ViewpointParameters car;
  car.own_extent_m = 2.8;
  const TargetCells own = targetCells(map, 10, 10, car);
  EXPECT_TRUE(own.size() > 700 && own.size() < 900) << own.size() << " cells: the car's 18 x 45, not the wall's";
  const auto viewpoint = chooseViewpoint(map, travel, 10, 10, {}, car);
  ASSERT_TRUE(viewpoint.has_value());
  EXPECT_LT(viewpoint->x, 9.1) << "seen from the open west side";
  EXPECT_TRUE(inLineOfSight(map, 6.0, 10.0, 10, 10, car, nullptr, &own));
  EXPECT_FALSE(inLineOfSight(map, 14.0, 10.0, 10, 10, car, nullptr, &own)) << "through the wall";
  // A car seen from one side only: its near side is its own too.
  auto side_only = makeCells(20, 20, kFree);
  fillRect(side_only, 9.1, 7.75, 9.2, 12.25, kOccupied);
  fillRect(side_only, 9.25, 7.75, 10.9, 12.25, kUnknown);
  const KnownMap seen_from_west(side_only, 0.45);
  const TargetCells near_side = targetCells(seen_from_west, 10, 10, car);
  EXPECT_GT(near_side.size(), 40u);
  EXPECT_TRUE(inLineOfSight(seen_from_west, 6.0, 10.0, 10, 10, car, nullptr, &near_side));
}

// A fire of 0.5 m radius fills cells up to about 0.55 m from its centre:
// beyond target_clearance_m, they would block the lines to its sides from
// every viewpoint unless they count as its body.
TEST(Viewpoints, AFiresOwnBodyDoesNotHideIt) {
  auto cells = makeCells(20, 20, kFree);
  fillFire(cells, 10.0, 10.0);
  const KnownMap map(cells, 0.45);
  const TravelField travel(map, 5.0, 10.0, 0.6);
  EXPECT_FALSE(chooseViewpoint(map, travel, 10, 10, {}, ViewpointParameters{}).has_value())
      << "its outermost cells hide it from everywhere";
  ViewpointParameters fire;
  fire.own_extent_m = ExplorerParameters{}.fire_extent_m;
  EXPECT_TRUE(chooseViewpoint(map, travel, 10, 10, {}, fire).has_value());
  const TargetCells own = targetCells(map, 10, 10, fire);
  EXPECT_TRUE(inLineOfSight(map, 10.0, 8.5, 10, 10, fire, nullptr, &own)) << "from 1.5 m";
}

TEST(TravelField, GoesAroundWallsAndTreatsUnknownAsFree) {
  auto cells = makeCells(20, 20, kUnknown);
  fillRect(cells, 9.9, 0.0, 10.1, 15.0, kOccupied);  // a wall with a gap at the top
  const KnownMap map(cells, 0.45);
  const TravelField travel(map, 5.0, 5.0, 0.6);
  Cell goal;
  ASSERT_TRUE(map.cellOf(15.0, 5.0, goal));
  ASSERT_TRUE(travel.reachable(goal.x, goal.y));
  EXPECT_GT(travel.at(goal.x, goal.y), 2 * 10.0);  // up, over the wall's end, and down again
}

TEST(Frontiers, FoundWhereTheKnownHalfMeetsTheUnknownHalf) {
  auto cells = makeCells(20, 10, kUnknown);
  fillRect(cells, 0.0, 0.0, 10.0, 10.0, kFree);  // the left half is known free
  const KnownMap map(cells, 0.45);
  const TravelField travel(map, 3.0, 5.0, 0.6);
  ExplorationMemory memory;
  memory.addStood({3.0, 5.0});
  const auto goals = findFrontiers(map, travel, memory);
  ASSERT_EQ(goals.size(), 1u);
  EXPECT_NEAR(goals[0].x, 9.95, 0.11);      // the last free column
  EXPECT_NEAR(goals[0].y, 5.0, 0.6);        // straight ahead of the robot
  EXPECT_NEAR(goals[0].yaw, 0.0, 10.0);     // facing the unknown (+x)
  EXPECT_GT(goals[0].size, 50);
  EXPECT_TRUE(frontierNear(map, memory, goals[0].x, goals[0].y, 1.0));

  // Once visited, that stretch no longer counts; the rest of the line still does.
  memory.addVisited({goals[0].x, goals[0].y});
  EXPECT_FALSE(frontierNear(map, memory, goals[0].x, goals[0].y, 1.0));
  const auto later = findFrontiers(map, travel, memory);
  ASSERT_FALSE(later.empty());
  EXPECT_GT(std::abs(later[0].y - goals[0].y), memory.parameters().visited_radius_m - 0.1);
}

TEST(Frontiers, NoneOnAFullyKnownMapNorAroundWhereTheRobotStood) {
  const KnownMap known(makeCells(20, 10, kFree), 0.45);
  const TravelField travel(known, 3.0, 5.0, 0.6);
  ExplorationMemory memory;
  EXPECT_TRUE(findFrontiers(known, travel, memory).empty());

  // The ground right around the robot is never seen, but it stood there.
  auto cells = makeCells(20, 10, kFree);
  fillRect(cells, 2.0, 4.0, 4.0, 6.0, kUnknown);
  const KnownMap blind(cells, 0.45);
  ExplorationMemory fresh;
  EXPECT_FALSE(findFrontiers(blind, travel, fresh).empty());
  ExplorationMemory stood;
  stood.addStood({3.0, 5.0});
  EXPECT_TRUE(findFrontiers(blind, travel, stood).empty());
}

TEST(Frontiers, UnreachableFrontiersAreIgnored) {
  auto cells = makeCells(20, 10, kFree);
  fillRect(cells, 14.0, 0.0, 20.0, 10.0, kUnknown);
  fillRect(cells, 9.9, 0.0, 10.1, 10.0, kOccupied);  // a wall across the whole world
  const KnownMap map(cells, 0.45);
  const TravelField travel(map, 3.0, 5.0, 0.6);
  ExplorationMemory memory;
  EXPECT_TRUE(findFrontiers(map, travel, memory).empty());
}

// A random width x height m world at 0.1 m: known free with walls, some unknown patches.
planners::ObstacleCells randomWorld(std::mt19937& rng, double width = 40, double height = 30) {
  auto cells = makeCells(width, height, kFree);
  std::uniform_real_distribution<double> x(0, width), y(0, height), length(1, 12);
  const int walls = static_cast<int>(25 * width * height / 1200);
  for (int i = 0; i < walls; ++i) {
    const double x0 = x(rng), y0 = y(rng);
    if (rng() % 2) fillRect(cells, x0, y0, x0 + length(rng), y0 + 0.2, kOccupied);
    else fillRect(cells, x0, y0, x0 + 0.2, y0 + length(rng), kOccupied);
  }
  for (int i = 0; i < 4; ++i) {
    const double x0 = x(rng), y0 = y(rng);
    fillRect(cells, x0, y0, x0 + 3, y0 + 3, kUnknown);
  }
  return cells;
}

// A map made from the one known before inflates only around what changed:
// its standing grid is the one made afresh, whether the map before made its
// own (or only one before it did), the radius or the size changed, or
// occupied cells came and went next to the border.
TEST(KnownMap, StandingFromTheMapKnownBeforeEqualsItMadeAfresh) {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 30; ++trial) {
    planners::ObstacleCells cells = randomWorld(rng, 20, 15);
    const double radius = trial % 5 == 4 ? 0.3 : 0.45;
    std::unique_ptr<KnownMap> known = std::make_unique<KnownMap>(cells, 0.45);
    for (int step = 0; step < 6; ++step) {
      if (step % 3 != 1) known->standing();  // sometimes the map before never made its grid
      std::uniform_real_distribution<double> x(-0.5, 20.5), y(-0.5, 15.5);
      for (int n = static_cast<int>(rng() % 4); n > 0; --n) {
        const double x0 = x(rng), y0 = y(rng);
        fillRect(cells, x0, y0, x0 + 0.6, y0 + 0.3, rng() % 3 ? kOccupied : kFree);
      }
      known = std::make_unique<KnownMap>(cells, step == 3 ? radius : 0.45, std::move(*known));
      const KnownMap fresh(cells, step == 3 ? radius : 0.45);
      ASSERT_EQ(known->standing().cells(), fresh.standing().cells()) << "trial " << trial << " step " << step;
    }
  }
  // A map of another size is made afresh.
  KnownMap small(makeCells(5, 5, kFree), 0.45);
  small.standing();
  const auto larger = makeCells(6, 5, kOccupied);
  EXPECT_EQ(KnownMap(larger, 0.45, std::move(small)).standing().cells(), KnownMap(larger, 0.45).standing().cells());
}

TEST(TravelField, WithinALimitIsTheFullAnswerUpToIt) {
  std::mt19937 rng(5);
  const KnownMap map(randomWorld(rng), 0.45);
  const TravelField full(map, 20.0, 15.0, 0.6);
  int compared = 0, beyond = 0;
  for (const double limit : {0.5, 3.0, 9.5, 24.0}) {
    const TravelField bounded(map, 20.0, 15.0, 0.6);  // grown only by the limited questions
    for (int i = 0; i < 3000; ++i) {
      const int cx = static_cast<int>(rng() % map.width()), cy = static_cast<int>(rng() % map.height());
      const double travel = full.at(cx, cy);
      const double answer = bounded.within(cx, cy, limit);
      if (travel <= limit) {
        ASSERT_EQ(answer, travel);
        ++compared;
      } else {
        ASSERT_TRUE(std::isinf(answer)) << "travel " << travel << " answered " << answer << " within " << limit;
        beyond += std::isfinite(travel) ? 1 : 0;
      }
    }
  }
  EXPECT_GT(compared, 1000);
  EXPECT_GT(beyond, 1000);
}

TEST(Viewpoints, WithAMaxCostTheSameViewpointOrNoneCheaper) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> x(1, 39), y(1, 29);
  int same = 0, none = 0;
  for (int world = 0; world < 6; ++world) {
    const KnownMap map(randomWorld(rng), 0.45);
    const TravelField travel(map, 20.0, 15.0, 0.6);
    for (int i = 0; i < 15; ++i) {
      const double tx = x(rng), ty = y(rng);
      const auto unbounded = chooseViewpoint(map, travel, tx, ty, {}, ViewpointParameters{});
      if (!unbounded) continue;
      // Asked again with growing limits, remembering the lines of sight: the same answers.
      SightMemory sights;
      const TravelField growing(map, 20.0, 15.0, 0.6);
      for (const double max_cost : {unbounded->cost - 4.0, unbounded->cost - 0.5, unbounded->cost}) {
        const auto again = chooseViewpoint(map, growing, tx, ty, {}, ViewpointParameters{}, max_cost, &sights);
        ASSERT_EQ(again.has_value(), unbounded->cost <= max_cost);
        if (again) {
          EXPECT_EQ(again->cost, unbounded->cost);
        }
      }
      for (const double max_cost : {unbounded->cost, unbounded->cost + 2.0, unbounded->cost - 0.5}) {
        const TravelField fresh(map, 20.0, 15.0, 0.6);
        const auto bounded = chooseViewpoint(map, fresh, tx, ty, {}, ViewpointParameters{}, max_cost);
        if (unbounded->cost <= max_cost) {
          ASSERT_TRUE(bounded.has_value());
          EXPECT_EQ(bounded->x, unbounded->x);
          EXPECT_EQ(bounded->y, unbounded->y);
          EXPECT_EQ(bounded->cost, unbounded->cost);
          ++same;
        } else {
          EXPECT_FALSE(bounded.has_value()) << "cost " << bounded->cost << " above " << max_cost;
          ++none;
        }
      }
    }
  }
  EXPECT_GT(same, 40);
  EXPECT_GT(none, 20);
}

// Searched outwards from the robot, the cheapest frontier is the first of
// every frontier's list, in long worlds with unknown patches near and far.
TEST(Frontiers, TheCheapestSearchedOutwardsIsTheFirstOfTheList) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> x(1, 139), y(1, 19);
  int compared = 0, far = 0;
  for (int world = 0; world < 40; ++world) {
    auto cells = randomWorld(rng, 140, 20);
    for (int patch = 0; patch < 1 + world % 6; ++patch) {
      const double px = x(rng), py = y(rng);
      fillRect(cells, px, py, px + 2 + world % 5, py + 2, kUnknown);
    }
    const KnownMap map(cells, 0.45);
    const Point robot{x(rng), y(rng)};
    const TravelField for_list(map, robot.x, robot.y, 0.6), for_search(map, robot.x, robot.y, 0.6);
    ExplorationMemory listed, searched;
    for (auto* memory : {&listed, &searched}) memory->addStood(robot);
    const auto goals = findFrontiers(map, for_list, listed);
    const auto cheapest = cheapestFrontier(map, for_search, searched, robot);
    ASSERT_EQ(cheapest.has_value(), !goals.empty()) << "world " << world;
    if (!cheapest) continue;
    EXPECT_EQ(cheapest->x, goals.front().x) << "world " << world;
    EXPECT_EQ(cheapest->y, goals.front().y) << "world " << world;
    EXPECT_EQ(cheapest->yaw, goals.front().yaw) << "world " << world;
    EXPECT_EQ(cheapest->travel_m, goals.front().travel_m) << "world " << world;
    EXPECT_EQ(cheapest->size, goals.front().size) << "world " << world;
    ++compared;
    far += cheapest->travel_m > 30 ? 1 : 0;
  }
  EXPECT_GT(compared, 30);
  EXPECT_GT(far, 2);
}

// Drives an Explorer through a scripted run: a small fake task stack that
// gives ids to pushed tasks and removes finished ones.
class FakeStack {
 public:
  void apply(const Decision& decision) {
    for (const auto& r : decision.requests) {
      if (r.type == TaskRequest::Type::Push) {
        StackEntry entry;
        entry.id = next_id_++;
        entry.parent = r.parent;
        entry.kind = r.kind;
        entry.object_id = r.object_id;
        entry.origin = r.parent == 0 ? "exploration" : "exploration";
        entries_.insert(entries_.begin(), entry);
        pushes.push_back(r);
      } else {
        finishes.push_back(r);
        removeWithChildren(r.task_id);
      }
    }
  }
  // The executor ran every sub-task of `parent`.
  void completeSubTasks(int64_t parent) {
    for (size_t i = 0; i < entries_.size();)
      if (entries_[i].parent == parent) entries_.erase(entries_.begin() + static_cast<long>(i));
      else ++i;
  }
  void removeWithChildren(int64_t id) {
    completeSubTasks(id);
    for (size_t i = 0; i < entries_.size();)
      if (entries_[i].id == id) entries_.erase(entries_.begin() + static_cast<long>(i));
      else ++i;
  }
  const std::vector<StackEntry>& entries() const { return entries_; }
  int64_t topComposite() const {
    for (const auto& e : entries_)
      if (e.parent == 0) return e.id;
    return 0;
  }

  std::vector<TaskRequest> pushes, finishes;

 private:
  std::vector<StackEntry> entries_;
  int64_t next_id_ = 1;
};

std::vector<TaskRequest> pushesOf(const Decision& decision) {
  std::vector<TaskRequest> pushes;
  for (const auto& r : decision.requests)
    if (r.type == TaskRequest::Type::Push) pushes.push_back(r);
  return pushes;
}

// An explorer's view of the world: the map and a robot standing at (x, y).
Observation observationAt(planners::ObstacleCells cells, double x, double y) {
  Observation o;
  o.map = std::make_shared<const planners::ObstacleCells>(std::move(cells));
  o.map_version = 1;
  o.robot_known = true;
  o.robot_x = x;
  o.robot_y = y;
  o.stack_known = true;
  return o;
}

// A person heard at (x, y), not yet seen; weight -1: DW gave none.
HypothesisView heardPerson(const std::string& id, double x, double y, double weight = -1) {
  HypothesisView h;
  h.object_id = id;
  h.x = x;
  h.y = y;
  h.heard = true;
  h.best_category = "person";
  h.confidence = h.person_confidence = 0.7;
  h.weight = weight;
  return h;
}

// The explorer searches outwards and stops once no farther hypothesis can
// win: it must choose what scoring every hypothesis's best viewpoint chooses.
TEST(ExplorerChoice, TheBoundedSearchChoosesWhatTheExhaustiveOneDoes) {
  // Long worlds: travels from a few metres to over a hundred.
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> x(1, 139), y(1, 19);
  const double weights[] = {-1, 0, 0.4, 1};  // -1: DW has none
  ExplorerParameters parameters;
  parameters.look_around = false;
  int chosen = 0, not_nearest = 0, far = 0;
  for (int world = 0; world < 60; ++world) {
    auto cells = randomWorld(rng, 140, 20);
    const double robot_x = x(rng), robot_y = y(rng);  // in this order: the worlds stay those of the seed
    Observation o = observationAt(std::move(cells), robot_x, robot_y);
    const int hypotheses = 1 + world % 8;
    for (int i = 0; i < hypotheses; ++i) {
      const double hx = x(rng), hy = y(rng);
      o.hypotheses.push_back(heardPerson("h" + std::to_string(i), hx, hy, weights[rng() % 4]));
    }
    // The reference: every hypothesis's best viewpoint, the lowest score, the first of equals.
    const KnownMap map(*o.map, o.robot_radius + parameters.safety_margin_m);
    const TravelField travel(map, o.robot_x, o.robot_y, o.robot_radius + parameters.safety_margin_m + 0.1);
    std::string best_id;
    Viewpoint best_viewpoint;
    double best_score = std::numeric_limits<double>::infinity();
    double nearest = std::numeric_limits<double>::infinity();
    std::string nearest_id;
    for (const auto& h : o.hypotheses) {
      const auto viewpoint = chooseViewpoint(map, travel, h.x, h.y, {}, parameters.viewpoints);
      if (!viewpoint) continue;
      const double score = viewpoint->cost - parameters.weight_gain_m * std::max(0.0, h.weight);
      if (score < best_score) {
        best_score = score;
        best_id = h.object_id;
        best_viewpoint = *viewpoint;
      }
      if (viewpoint->travel_m < nearest) {
        nearest = viewpoint->travel_m;
        nearest_id = h.object_id;
      }
    }
    Explorer explorer(parameters);
    const Decision decision = explorer.step(o);
    const auto pushes = pushesOf(decision);
    if (best_id.empty()) {
      EXPECT_TRUE(pushes.empty() || pushes.front().kind != "verify") << "world " << world;
      continue;
    }
    ASSERT_FALSE(pushes.empty()) << "world " << world;
    EXPECT_EQ(pushes.front().object_id, best_id) << "world " << world;
    EXPECT_EQ(pushes.front().x, best_viewpoint.x) << "world " << world;
    EXPECT_EQ(pushes.front().y, best_viewpoint.y) << "world " << world;
    ++chosen;
    not_nearest += best_id != nearest_id ? 1 : 0;
    far += best_score > 40 ? 1 : 0;
  }
  EXPECT_GT(chosen, 45);
  EXPECT_GT(not_nearest, 3);  // the weights decided some choices
  EXPECT_GT(far, 3);          // and the nearest viewpoints were far in some
}

// The bounded search must still look far enough for a weight: a sound that
// matters 30 m away beats one that does not 15 m away.
TEST(ExplorerChoice, AFarHypothesisThatMattersBeatsANearOneThatDoesNot) {
  ExplorerParameters parameters;
  parameters.look_around = false;
  Observation o = observationAt(makeCells(100, 10, kFree), 5, 5);
  o.hypotheses = {heardPerson("near", 20, 5, -1), heardPerson("far", 38, 5, 1)};
  Explorer explorer(parameters);
  const auto pushes = pushesOf(explorer.step(o));
  ASSERT_FALSE(pushes.empty());
  EXPECT_EQ(pushes.front().object_id, "far");
  EXPECT_GT(std::hypot(pushes.front().x - o.robot_x, pushes.front().y - o.robot_y), 25.0);
}

// A hypothesis near the robot but behind a wall scores far more than its
// straight-line bound; one farther off in the open scores a little less.
// The search must not stop at the walled one: the open one's bound is below it.
TEST(ExplorerChoice, AnOpenHypothesisBeatsANearerWalledOne) {
  ExplorerParameters parameters;
  parameters.look_around = false;
  auto cells = makeCells(80, 30, kFree);
  fillRect(cells, 32.0, 2.0, 32.2, 24.0, kOccupied);  // between the robot and the walled one
  const KnownMap map(cells, 0.35 + parameters.safety_margin_m);
  const TravelField travel(map, 30, 13, 0.35 + parameters.safety_margin_m + 0.1);
  const auto walled = chooseViewpoint(map, travel, 34.5, 13, {}, parameters.viewpoints);
  ASSERT_TRUE(walled);
  // The open one, straight behind the robot, scoring about half a metre less.
  const double open_x = 30 - (walled->cost + 3.5);
  const auto open = chooseViewpoint(map, travel, open_x, 13, {}, parameters.viewpoints);
  ASSERT_TRUE(open);
  ASSERT_LT(open->cost, walled->cost);
  ASSERT_GT(open->cost, walled->cost - 1.5);
  Observation o = observationAt(cells, 30, 13);
  o.robot_radius = 0.35;
  o.hypotheses = {heardPerson("walled", 34.5, 13), heardPerson("open", open_x, 13)};
  Explorer explorer(parameters);
  const auto pushes = pushesOf(explorer.step(o));
  ASSERT_FALSE(pushes.empty());
  EXPECT_EQ(pushes.front().object_id, "open");
}

class ExplorerRun : public ::testing::Test {
 protected:
  void SetUp() override {
    observation.robot_known = true;
    observation.robot_x = 5;
    observation.robot_y = 10;
    observation.robot_yaw = 0;
    observation.robot_radius = 0.35;
    observation.duration = 120;
    setMap(wallWorld());
  }
  void setMap(planners::ObstacleCells cells) {
    observation.map = std::make_shared<const planners::ObstacleCells>(std::move(cells));
    ++observation.map_version;
  }
  Decision tick() {
    observation.stack = stack.entries();
    observation.stack_known = true;
    Decision decision = explorer.step(observation);
    stack.apply(decision);
    observation.t += 0.1;
    return decision;
  }
  // Runs the look-around until its turns are done; the next tick ends it
  // and decides what comes next.
  // The next verify viewpoint of victim1 (at 12, 10) is pushed; on the way a
  // wall is mapped into `map` between it and the target, which rules it out
  // (the job ends); then `map` is back. Its goal is added to `goals`.
  void ruleOutNextViewpoint(const planners::ObstacleCells& map, std::vector<Point>& goals) {
    const auto subs = pushesOf(tick());
    ASSERT_EQ(subs.size(), 2u) << "viewpoint " << goals.size();
    ASSERT_EQ(subs[0].kind, "goto");
    goals.push_back({subs[0].x, subs[0].y});
    auto cells = map;
    const double mx = 0.5 * (subs[0].x + 12.0), my = 0.5 * (subs[0].y + 10.0);
    fillRect(cells, mx - 0.6, my - 0.6, mx + 0.6, my + 0.6, kOccupied);
    setMap(cells);
    const size_t finishes = stack.finishes.size();
    for (int i = 0; i < 30 && stack.finishes.size() == finishes; ++i) tick();
    ASSERT_EQ(stack.finishes.size(), finishes + 1);
    setMap(map);
  }

  // The sub-tasks of the verify composite pushed last are pushed; the robot
  // gets there and looks; after the dwell the attempt fails (and the next
  // composite, if any, is pushed in that tick).
  void failNextLook() {
    const auto subs = pushesOf(tick());
    ASSERT_EQ(subs.size(), 2u);
    stack.completeSubTasks(subs[0].parent);
    const size_t finishes = stack.finishes.size();
    for (int i = 0; i < 30 && stack.finishes.size() == finishes; ++i) tick();
    ASSERT_EQ(stack.finishes.size(), finishes + 1);
  }

  void lookAround() {
    tick();  // pushes the composite
    tick();  // pushes its turns
    stack.completeSubTasks(stack.topComposite());
  }
  HypothesisView hidden(const std::string& id = "victim1") {
    HypothesisView h;
    h.object_id = id;
    h.x = 12;
    h.y = 10;
    h.heard = true;
    h.best_category = "person";
    h.confidence = 0.7;
    h.person_confidence = 0.7;
    h.weight = 0.75;
    return h;
  }

  // These runs are about targets and frontiers: the ground is looked at
  // closely only where a test says so (CloseLookRun).
  static ExplorerParameters withoutCloseLooks() {
    ExplorerParameters p;
    p.close_looks.enabled = false;
    return p;
  }

  ExplorerParameters parameters = withoutCloseLooks();
  Explorer explorer{parameters};
  FakeStack stack;
  Observation observation;
};

TEST_F(ExplorerRun, LooksAroundFirstWithFourQuarterTurns) {
  const Decision first = tick();
  ASSERT_EQ(first.requests.size(), 1u);
  EXPECT_EQ(first.requests[0].kind, "explore");
  EXPECT_EQ(first.requests[0].parent, 0);
  EXPECT_EQ(explorer.phase(), Explorer::Phase::LookAround);
  const Decision second = tick();
  ASSERT_EQ(second.requests.size(), 4u);
  // In the order they run: a quarter turn at a time, back to the start heading.
  const double expected_yaw[] = {90, 180, -90, 0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(second.requests[i].kind, "turn");
    EXPECT_NEAR(std::remainder(second.requests[i].yaw - expected_yaw[i], 360.0), 0, 1e-9) << i;
  }
  for (const auto& r : second.requests) EXPECT_EQ(r.parent, 1);
  tick();  // turning: nothing to do
  EXPECT_TRUE(stack.finishes.empty());
  stack.completeSubTasks(1);
  tick();
  ASSERT_EQ(stack.finishes.size(), 1u);
  EXPECT_EQ(stack.finishes[0].task_id, 1);
  EXPECT_TRUE(stack.finishes[0].success);
}

TEST_F(ExplorerRun, VerifiesAHiddenHypothesisFromAroundTheWallAndFinishesWhenVerified) {
  lookAround();
  observation.hypotheses = {hidden()};
  const Decision start = tick();
  EXPECT_EQ(stack.finishes.size(), 1u);  // the look-around
  const auto composites = pushesOf(start);
  ASSERT_EQ(composites.size(), 1u);
  EXPECT_EQ(composites[0].kind, "verify");
  EXPECT_EQ(composites[0].object_id, "victim1");
  EXPECT_EQ(composites[0].priority, parameters.verify_priority);
  EXPECT_EQ(explorer.phase(), Explorer::Phase::Verify);

  const auto subs = pushesOf(tick());
  ASSERT_EQ(subs.size(), 2u);
  const TaskRequest& go = subs[0];  // sub-tasks run in the order pushed
  const TaskRequest& look = subs[1];
  EXPECT_EQ(look.kind, "look_at");
  EXPECT_EQ(look.object_id, "victim1");
  EXPECT_EQ(go.kind, "goto");
  EXPECT_EQ(go.parent, look.parent);
  EXPECT_FALSE(segmentHitsRect(go.x, go.y, 12, 10, 9.9, 4.0, 10.1, 16.0));
  EXPECT_NEAR(go.yaw, bearingDeg(go.x, go.y, 12, 10), 1e-9);

  tick();  // on its way
  EXPECT_EQ(stack.finishes.size(), 1u);
  observation.hypotheses[0].seen = true;
  observation.hypotheses[0].verified = true;
  tick();
  ASSERT_EQ(stack.finishes.size(), 2u);
  EXPECT_EQ(stack.finishes[1].task_id, go.parent);
  EXPECT_TRUE(stack.finishes[1].success);
  EXPECT_EQ(explorer.attempts("victim1"), 0);
}

TEST_F(ExplorerRun, TriesAnotherViewpointWhenStillUnseenAndGivesUpAfterTheLimit) {
  parameters.verify_attempts = 2;
  explorer = Explorer(parameters);
  lookAround();
  observation.hypotheses = {hidden()};
  tick();  // ends the look-around, pushes the first verify composite
  std::vector<Point> goals;
  Decision last;
  for (int attempt = 0; attempt < 2; ++attempt) {
    const auto subs = pushesOf(tick());
    ASSERT_EQ(subs.size(), 2u) << "attempt " << attempt;
    ASSERT_EQ(subs[0].kind, "goto");
    goals.push_back({subs[0].x, subs[0].y});
    stack.completeSubTasks(subs[0].parent);  // got there and looked
    const size_t finishes = stack.finishes.size();
    for (int i = 0; i < 30 && stack.finishes.size() == finishes; ++i) last = tick();  // dwell, then fail
    ASSERT_EQ(stack.finishes.size(), finishes + 1);
    EXPECT_FALSE(stack.finishes.back().success);
    EXPECT_EQ(explorer.attempts("victim1"), attempt + 1);
  }
  EXPECT_GE(std::hypot(goals[0].x - goals[1].x, goals[0].y - goals[1].y), parameters.viewpoints.tried_radius_m);
  EXPECT_TRUE(explorer.givenUp("victim1"));
  ASSERT_EQ(explorer.triedViewpoints("victim1").size(), 2u);

  // The map is fully known and nothing is left: the run stops, saying why.
  ASSERT_TRUE(last.stop.has_value());
  EXPECT_NE(last.stop->find("1 given up"), std::string::npos) << *last.stop;
  EXPECT_TRUE(explorer.stopped());
}

// A heard place that a look had in plain view (in the camera's view, near,
// every cell of the sight line known and free) and that still did not
// settle holds nothing: it is given up after that one look, unless the
// estimate was out of view, was only a point along a heard bearing (not
// located: the source may be farther on), or the rule is off.
TEST_F(ExplorerRun, AHeardPlaceSeenEmptyInPlainViewIsGivenUpAfterOneLook) {
  std::string logged;
  const auto lookOnce = [&](ExplorerParameters p, double head_yaw_off_target, bool located = true) {
    logged.clear();
    explorer = Explorer(p);
    stack = FakeStack{};
    observation.t = 0;
    observation.robot_x = 5;
    observation.robot_y = 10;
    observation.robot_yaw = 0;
    observation.head_yaw = 0;
    observation.hypotheses.clear();
    lookAround();
    HypothesisView heard = hidden();
    heard.x = 5;  // on the robot's side of the wall, in the open
    heard.y = 13;
    heard.located = located;
    observation.hypotheses = {heard};
    tick();  // ends the look-around, pushes the verify composite
    const auto subs = pushesOf(tick());
    EXPECT_EQ(subs.size(), 2u);
    if (subs.size() != 2u) return;
    observation.robot_x = subs[0].x;  // the robot got there and faces the place (or looks aside)
    observation.robot_y = subs[0].y;
    observation.robot_yaw = subs[0].yaw;
    observation.head_yaw = head_yaw_off_target;
    stack.completeSubTasks(subs[0].parent);
    const size_t finishes = stack.finishes.size();
    for (int i = 0; i < 30 && stack.finishes.size() == finishes; ++i)
      for (const auto& line : tick().log) logged += line + "\n";
    EXPECT_EQ(stack.finishes.size(), finishes + 1);
    EXPECT_EQ(explorer.attempts("victim1"), 1);
  };
  ExplorerParameters p = parameters;
  EXPECT_TRUE(p.give_up_in_plain_view);  // the default
  ASSERT_GT(p.verify_attempts, 1);
  lookOnce(p, 0);
  EXPECT_TRUE(explorer.givenUp("victim1"));
  EXPECT_NE(logged.find("victim1: given up: nothing where it was heard, (5.0, 13.0), in plain view from"),
            std::string::npos) << logged;

  lookOnce(p, 120);  // the head turned away: the place was not in view
  EXPECT_FALSE(explorer.givenUp("victim1"));

  lookOnce(p, 0, false);  // in view, but only a point along the bearing
  EXPECT_FALSE(explorer.givenUp("victim1"));

  p.give_up_in_plain_view = false;
  lookOnce(p, 0);
  EXPECT_FALSE(explorer.givenUp("victim1"));
}

// A wall mapped on the way between the chosen viewpoint and the target rules
// that viewpoint out: another is chosen, and no attempt is spent (a target
// behind walls being mapped piece by piece is not given up for it), up to
// ruled_out_viewpoints.
TEST_F(ExplorerRun, AViewpointTheMapRulesOutIsNotAnAttempt) {
  parameters.verify_attempts = 1;
  parameters.ruled_out_viewpoints = 2;
  explorer = Explorer(parameters);
  lookAround();
  observation.hypotheses = {hidden()};
  tick();  // ends the look-around, pushes the first verify composite
  std::vector<Point> goals;
  for (int ruled_out = 0; ruled_out < 2; ++ruled_out) {
    // On the way, a wall is mapped right in front of the target, on the viewpoint's side.
    ASSERT_NO_FATAL_FAILURE(ruleOutNextViewpoint(wallWorld(), goals));
    EXPECT_EQ(explorer.attempts("victim1"), 0);
  }
  EXPECT_GE(std::hypot(goals[0].x - goals[1].x, goals[0].y - goals[1].y), parameters.viewpoints.tried_radius_m);
  EXPECT_TRUE(explorer.givenUp("victim1"));  // after two ruled out
}

// While the target's surroundings are still being mapped (here: an unknown
// patch within the viewpoints' reach of it, so a frontier is near), the
// viewpoints the map rules out do not count, up to ruled_out_while_mapping:
// a house mapped wall by wall is not given up before its open side is seen.
TEST_F(ExplorerRun, ViewpointsRuledOutWhileTheSurroundingsAreMappedDoNotCount) {
  parameters.verify_attempts = 1;
  parameters.ruled_out_viewpoints = 2;
  parameters.ruled_out_while_mapping = 2;
  explorer = Explorer(parameters);
  const auto beingMapped = [] {
    auto cells = wallWorld();
    fillRect(cells, 15.0, 13.0, 17.0, 15.0, kUnknown);  // 4.2 to 7.1 m from the target
    return cells;
  };
  setMap(beingMapped());
  lookAround();
  observation.hypotheses = {hidden()};
  tick();  // ends the look-around, pushes the first verify composite
  std::vector<Point> goals;
  for (int ruled_out = 0; ruled_out < 4; ++ruled_out) {
    EXPECT_FALSE(explorer.givenUp("victim1")) << "after " << ruled_out << " ruled out";
    ASSERT_NO_FATAL_FAILURE(ruleOutNextViewpoint(beingMapped(), goals));
    EXPECT_EQ(explorer.attempts("victim1"), 0);
  }
  // Two while mapping, then the two the limit allows.
  EXPECT_TRUE(explorer.givenUp("victim1"));
  EXPECT_EQ(explorer.triedViewpoints("victim1").size(), 4u);
}

// Once the target was looked at from somewhere, a viewpoint the map rules
// out counts as one more failed attempt.
TEST_F(ExplorerRun, AfterALookARuledOutViewpointIsAnAttempt) {
  parameters.verify_attempts = 2;
  explorer = Explorer(parameters);
  lookAround();
  observation.hypotheses = {hidden()};
  tick();
  auto subs = pushesOf(tick());
  ASSERT_EQ(subs.size(), 2u);
  stack.completeSubTasks(subs[0].parent);  // got there and looked
  size_t finishes = stack.finishes.size();
  for (int i = 0; i < 30 && stack.finishes.size() == finishes; ++i) tick();  // dwell, then fail
  ASSERT_EQ(explorer.attempts("victim1"), 1);
  subs = pushesOf(tick());
  ASSERT_EQ(subs.size(), 2u);
  auto cells = wallWorld();
  const double mx = 0.5 * (subs[0].x + 12.0), my = 0.5 * (subs[0].y + 10.0);
  fillRect(cells, mx - 0.6, my - 0.6, mx + 0.6, my + 0.6, kOccupied);
  setMap(cells);
  finishes = stack.finishes.size();
  for (int i = 0; i < 30 && stack.finishes.size() == finishes; ++i) tick();
  EXPECT_EQ(explorer.attempts("victim1"), 2);
  EXPECT_TRUE(explorer.givenUp("victim1"));
}

// When nothing else is left, a hypothesis given up where it was placed is
// tried again once it is placed moved_m away (a heard estimate that had
// been pulled towards another source of the same sound), tries_after_moving
// times at most.
TEST_F(ExplorerRun, AHypothesisGivenUpIsTriedAgainWhenItIsPlacedFarFromThere) {
  parameters.verify_attempts = 1;
  parameters.tries_after_moving = 1;
  parameters.stop_when_done = false;  // keeps watching once all is given up
  explorer = Explorer(parameters);
  lookAround();
  observation.hypotheses = {hidden()};
  tick();  // ends the look-around, pushes the verify composite
  ASSERT_NO_FATAL_FAILURE(failNextLook());
  ASSERT_TRUE(explorer.givenUp("victim1"));
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(pushesOf(tick()).empty());

  observation.hypotheses[0].y = 15;  // 5 m away: not far enough
  for (int i = 0; i < 40; ++i) EXPECT_TRUE(pushesOf(tick()).empty());
  EXPECT_TRUE(explorer.givenUp("victim1"));

  observation.hypotheses[0].x = 3;  // now 11.4 m from (12, 10)
  observation.hypotheses[0].y = 3;
  std::vector<TaskRequest> again;  // at the next look for work (idle_recheck_s)
  for (int i = 0; i < 30 && again.empty(); ++i) again = pushesOf(tick());
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0].kind, "verify");
  EXPECT_EQ(again[0].object_id, "victim1");
  EXPECT_FALSE(explorer.givenUp("victim1"));
  EXPECT_EQ(explorer.attempts("victim1"), 0);
  ASSERT_NO_FATAL_FAILURE(failNextLook());
  ASSERT_TRUE(explorer.givenUp("victim1"));

  observation.hypotheses[0].x = 15;  // moved again, but its one try after moving is spent
  observation.hypotheses[0].y = 17;
  for (int i = 0; i < 40; ++i) EXPECT_TRUE(pushesOf(tick()).empty());
  EXPECT_TRUE(explorer.givenUp("victim1"));
}

TEST_F(ExplorerRun, AHypothesisPlacedFarFromWhereItsViewpointsFailedIsTriedAfresh) {
  parameters.verify_attempts = 2;
  parameters.tries_after_moving = 2;
  explorer = Explorer(parameters);
  lookAround();
  observation.hypotheses = {hidden()};
  tick();  // pushes the verify composite
  ASSERT_NO_FATAL_FAILURE(failNextLook());  // at (12, 10)
  ASSERT_EQ(explorer.attempts("victim1"), 1);

  // Its estimate jumps 11.4 m while the robot goes to the next viewpoint:
  // that job ends without counting, and the new place starts from none.
  observation.hypotheses[0].x = 3;
  observation.hypotheses[0].y = 3;
  std::vector<TaskRequest> look;
  for (int i = 0; i < 30 && look.empty(); ++i)
    for (const auto& push : pushesOf(tick()))
      if (push.kind == "look_at" && std::hypot(push.x - 3, push.y - 3) < 0.01) look.push_back(push);
  ASSERT_EQ(look.size(), 1u) << "no look at the new place";
  EXPECT_FALSE(explorer.givenUp("victim1")) << "the jump cost its last attempt";
  EXPECT_EQ(explorer.attempts("victim1"), 0);
  for (const auto& tried : explorer.triedViewpoints("victim1"))
    EXPECT_GT(std::hypot(tried.x - 12, tried.y - 10), 6.5) << "a viewpoint of the old place still counts";
  stack.completeSubTasks(look[0].parent);
  for (int i = 0; i < 30 && explorer.attempts("victim1") == 0; ++i) tick();
  ASSERT_EQ(explorer.attempts("victim1"), 1);

  // Placed 10 m on, on the way to the next viewpoint, while the robot went
  // 10 m too: an estimate still only on its bearing, which moves with the
  // robot, is no jump. The viewpoint it left behind is a failed attempt.
  observation.robot_x = 15;
  observation.hypotheses[0].x = 13;
  bool gave_up = false, afresh = false;
  for (int i = 0; i < 60 && !gave_up && !afresh; ++i) {
    for (const auto& line : tick().log) {
      gave_up = gave_up || line.find("given up after 2 viewpoints") != std::string::npos;
      afresh = afresh || line.find("tried afresh") != std::string::npos;
    }
  }
  EXPECT_TRUE(gave_up);
  EXPECT_FALSE(afresh) << "an estimate that moved with the robot was taken for a jump";
}

TEST_F(ExplorerRun, AHeardFireIsLookedAtThoughItsBodyFillsItsSurroundings) {
  parameters.stop_when_done = false;  // keeps watching after the siren is found to have no viewpoint
  explorer = Explorer(parameters);
  auto cells = wallWorld();
  fillFire(cells, 15.0, 10.0);
  setMap(cells);
  lookAround();
  HypothesisView fire = hidden("fire1");
  fire.x = 15;
  fire.best_category = "fire";
  HypothesisView siren = fire;  // the same cells, taken for what is not a fire
  siren.object_id = "siren1";
  siren.best_category = "siren";
  observation.hypotheses = {siren};
  for (int i = 0; i < 5; ++i)
    for (const auto& push : pushesOf(tick())) EXPECT_NE(push.kind, "verify") << "its cells hide it from everywhere";
  observation.hypotheses = {fire};
  std::vector<TaskRequest> pushed;
  for (int i = 0; i < 80 && pushed.empty(); ++i)
    for (const auto& push : pushesOf(tick()))
      if (push.kind == "verify") pushed.push_back(push);
  ASSERT_EQ(pushed.size(), 1u) << "a fire's body is its own";
  EXPECT_EQ(pushed[0].object_id, "fire1");
}

TEST_F(ExplorerRun, ExploresTheUnknownAndStopsWhenAllIsSettledAndKnown) {
  auto cells = makeCells(20, 20, kUnknown);
  fillRect(cells, 0.0, 0.0, 10.0, 20.0, kFree);
  setMap(cells);
  lookAround();
  const auto explore = pushesOf(tick());
  ASSERT_EQ(explore.size(), 1u);
  EXPECT_EQ(explore[0].kind, "explore");
  EXPECT_EQ(explorer.phase(), Explorer::Phase::Explore);
  const auto subs = pushesOf(tick());
  ASSERT_EQ(subs.size(), 1u);
  EXPECT_EQ(subs[0].kind, "goto");
  EXPECT_NEAR(subs[0].x, 9.95, 0.11);
  EXPECT_NEAR(subs[0].yaw, 0.0, 10.0);

  // A heard hypothesis interrupts exploring.
  observation.hypotheses = {hidden()};
  observation.hypotheses[0].x = 7;  // in plain view
  const auto verify = pushesOf(tick());
  ASSERT_EQ(stack.finishes.size(), 2u);
  EXPECT_TRUE(stack.finishes.back().success);
  ASSERT_EQ(verify.size(), 1u);
  EXPECT_EQ(verify[0].kind, "verify");
  EXPECT_EQ(explorer.phase(), Explorer::Phase::Verify);
  tick();
  observation.hypotheses[0].seen = observation.hypotheses[0].verified = true;
  tick();
  EXPECT_EQ(stack.finishes.size(), 3u);
  EXPECT_EQ(explorer.phase(), Explorer::Phase::Explore);  // back to the frontier

  // The robot went and saw everything: nothing left, the run stops.
  setMap(makeCells(20, 20, kFree));
  Decision last;
  for (int i = 0; i < 20 && !last.stop; ++i) last = tick();
  ASSERT_TRUE(last.stop.has_value());
  EXPECT_NE(last.stop->find("1 verified"), std::string::npos) << *last.stop;
  EXPECT_NE(last.stop->find("no reachable frontier"), std::string::npos) << *last.stop;
}

// A heard hypothesis only on its bearing (not located) neither interrupts
// exploring nor is verified while a frontier is left; once none is, it is.
// Located, it interrupts at once (the test above).
TEST_F(ExplorerRun, AHeardEstimateNotYetLocatedWaitsUntilNothingElseIsLeft) {
  auto cells = makeCells(20, 20, kUnknown);
  fillRect(cells, 0.0, 0.0, 10.0, 20.0, kFree);
  setMap(cells);
  observation.hypotheses = {hidden()};
  observation.hypotheses[0].x = 7;
  observation.hypotheses[0].located = false;
  lookAround();
  const auto explore = pushesOf(tick());
  ASSERT_EQ(explore.size(), 1u);
  EXPECT_EQ(explore[0].kind, "explore") << "the frontier first";
  for (int i = 0; i < 5; ++i) {
    for (const auto& push : pushesOf(tick())) EXPECT_NE(push.kind, "verify");
  }
  EXPECT_EQ(explorer.phase(), Explorer::Phase::Explore);

  // The frontier is mapped: nothing else left, the estimate is verified.
  setMap(makeCells(20, 20, kFree));
  std::vector<std::string> kinds;
  for (int i = 0; i < 20 && kinds.empty(); ++i)
    for (const auto& push : pushesOf(tick())) kinds.push_back(push.kind);
  ASSERT_FALSE(kinds.empty());
  EXPECT_EQ(kinds[0], "verify");
  EXPECT_EQ(explorer.phase(), Explorer::Phase::Verify);

  // With verify_located_first off it interrupts exploring at once.
  ExplorerParameters at_once = withoutCloseLooks();
  at_once.verify_located_first = false;
  Explorer eager(at_once);
  FakeStack eager_stack;
  Observation seen = observation;
  seen.t = 0;
  seen.map = std::make_shared<const planners::ObstacleCells>(cells);
  ++seen.map_version;
  bool verified = false;
  for (int i = 0; i < 10 && !verified; ++i) {
    seen.stack = eager_stack.entries();
    seen.stack_known = true;
    const Decision decision = eager.step(seen);
    eager_stack.apply(decision);
    eager_stack.completeSubTasks(eager_stack.topComposite());
    seen.t += 0.1;
    for (const auto& request : decision.requests) verified |= request.kind == "verify";
  }
  EXPECT_TRUE(verified);
}

TEST_F(ExplorerRun, FalsifiedCountsAsSettled) {
  lookAround();
  HypothesisView radio = hidden("radio");
  radio.seen = true;
  radio.falsified = true;
  observation.hypotheses = {radio};
  const Decision d = tick();
  ASSERT_TRUE(d.stop.has_value());
  EXPECT_NE(d.stop->find("1 falsified"), std::string::npos) << *d.stop;
}

TEST_F(ExplorerRun, StopsWhenTheDurationEnds) {
  lookAround();
  observation.hypotheses = {hidden()};
  tick();
  tick();
  observation.t = observation.duration;
  const Decision d = tick();
  ASSERT_TRUE(d.stop.has_value());
  EXPECT_NE(d.stop->find("duration"), std::string::npos);
  ASSERT_EQ(stack.finishes.size(), 2u);
  EXPECT_FALSE(stack.finishes.back().success);  // the running verify task is ended
  // Asked again, it says the same.
  EXPECT_EQ(tick().stop, d.stop);
}

TEST_F(ExplorerRun, WithoutStopWhenDoneItWatchesForNewSoundsUntilTheDuration) {
  parameters.stop_when_done = false;
  explorer = Explorer(parameters);
  lookAround();
  const Decision done = tick();  // nothing heard, everything known
  EXPECT_FALSE(done.stop.has_value());
  EXPECT_EQ(explorer.phase(), Explorer::Phase::Idle);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(tick().requests.empty());
  observation.hypotheses = {hidden()};  // someone starts yelling
  const auto pushes = pushesOf(tick());
  ASSERT_EQ(pushes.size(), 1u);
  EXPECT_EQ(pushes[0].kind, "verify");
  observation.t = observation.duration;
  const Decision end = tick();
  ASSERT_TRUE(end.stop.has_value());
  EXPECT_NE(end.stop->find("duration"), std::string::npos);
}

TEST_F(ExplorerRun, PrefersTheHypothesisWithTheHigherWeight) {
  lookAround();
  HypothesisView near = hidden("near");
  near.x = 7;  // close and in view
  near.weight = 0.25;
  HypothesisView urgent = hidden("urgent");
  urgent.weight = 1.0;  // behind the wall, but yelling
  observation.hypotheses = {near, urgent};
  const auto pushes = pushesOf(tick());
  ASSERT_EQ(pushes.size(), 1u);
  EXPECT_EQ(pushes[0].object_id, "urgent");
}

TEST_F(ExplorerRun, InspectsAGlimpsedPossiblePersonButNotAClearWall) {
  lookAround();
  HypothesisView far;
  far.object_id = "figure";
  far.x = 2;
  far.y = 18;
  far.glimpsed = true;
  far.best_category = "person";  // barely: every label is near 0.5 so far away
  far.confidence = 0.51;
  far.person_confidence = 0.51;
  HypothesisView wall = far;
  wall.object_id = "wall2";
  wall.x = 18;
  wall.best_category = "wall";
  wall.confidence = 0.7;
  wall.person_confidence = 0.3;
  observation.hypotheses = {wall, far};
  const auto pushes = pushesOf(tick());
  ASSERT_EQ(pushes.size(), 1u);
  EXPECT_EQ(pushes[0].kind, "verify");
  EXPECT_EQ(pushes[0].object_id, "figure");
}

// A house of three walls, its open side facing north, in a known free
// 40 x 20 m world: walls x = 30..36 at y = 4 (south), x = 30 and x = 36
// from y = 4 to 10.
planners::ObstacleCells houseWorld() {
  auto cells = makeCells(40, 20, kFree);
  fillRect(cells, 30.0, 3.9, 36.0, 4.1, kOccupied);
  fillRect(cells, 29.9, 4.0, 30.1, 10.0, kOccupied);
  fillRect(cells, 35.9, 4.0, 36.1, 10.0, kOccupied);
  return cells;
}

TEST(CloseLooks, GroundIsLookedAtCloselyOnlyInViewInRangeAndInSight) {
  auto cells = makeCells(20, 20, kFree);
  fillRect(cells, 7.9, 10.5, 8.1, 16.0, kOccupied);  // a wall north-east of the camera
  fillRect(cells, 3.0, 14.0, 5.0, 16.0, kUnknown);   // ground not mapped yet
  const KnownMap map(cells, 0.5);
  CloseLookParameters parameters;
  parameters.range_m = 6.0;
  CloseLookCoverage coverage(parameters);
  coverage.look(map, 5, 10, 45);  // gazing north-east
  EXPECT_FALSE(coverage.open(7.1, 12.1)) << "in view, 3 m away, in sight";
  EXPECT_TRUE(coverage.open(9.1, 13.1)) << "in view and range, behind the wall";
  EXPECT_TRUE(coverage.open(5.1, 4.1)) << "behind the camera";
  EXPECT_TRUE(coverage.open(10.6, 15.6)) << "in view, 7.9 m away";
  EXPECT_TRUE(coverage.open(4.1, 15.1)) << "not known to be ground when looked at";
  const int looked = coverage.lookedAtCells();
  EXPECT_GT(looked, 20);
  coverage.look(map, 5.1, 10, 50);  // hardly moved: not marked again
  EXPECT_EQ(coverage.lookedAtCells(), looked);
  coverage.look(map, 5, 10, 225);  // turned round
  EXPECT_FALSE(coverage.open(3.1, 8.1));
  EXPECT_GT(coverage.lookedAtCells(), looked);
}

// Goes from goal to goal as the explorer would, looking at each and turning
// as the goal says, until no patch is left; the goals' count and the travel.
struct CloseLookSearch {
  int goals = 0;
  double travelled = 0;
};
CloseLookSearch searchTheGround(const KnownMap& map, CloseLookCoverage& coverage, Point robot) {
  CloseLookSearch search;
  while (auto goal = coverage.cheapestPatch(map, TravelField(map, robot.x, robot.y, 0.6), robot)) {
    EXPECT_LT(++search.goals, 200) << "the search must end";
    if (search.goals >= 200) break;
    Cell cell;
    EXPECT_TRUE(map.cellOf(goal->x, goal->y, cell));
    EXPECT_TRUE(map.standable(cell.x, cell.y));
    EXPECT_TRUE(coverage.open(goal->x, goal->y));
    search.travelled += goal->travel_m;
    robot = {goal->x, goal->y};
    coverage.look(map, goal->x, goal->y, goal->yaw);
    double heading = goal->yaw;
    for (const double turn : goal->turns) {  // turning the shorter way, marked every 10 degrees
      const double span = std::remainder(turn - heading, 360.0);
      EXPECT_LE(std::abs(span), 90.0 + 1e-9);
      for (int step = 1; step <= 9; ++step) coverage.look(map, goal->x, goal->y, heading + span * step / 9.0);
      heading = turn;
    }
    coverage.visited(map, {goal->x, goal->y});
  }
  return search;
}

TEST(CloseLooks, PatchByPatchTheReachableGroundIsLookedAtAndTheSearchEnds) {
  const auto cells = houseWorld();
  const KnownMap map(cells, 0.5);
  CloseLookCoverage coverage;
  const Point start{3, 10};
  coverage.look(map, start.x, start.y, 0);
  const CloseLookSearch search = searchTheGround(map, coverage, start);
  EXPECT_GT(search.goals, 3);
  // The house's floor, which depth maps from the far side of the world, was
  // looked at from up close.
  EXPECT_FALSE(coverage.open(33.1, 6.1));
  EXPECT_FALSE(coverage.open(31.1, 5.1));
  // Most of the ground was looked at, not merely given up.
  const double free_cells = (40.0 * 20.0 - 14.0) / 0.25;
  EXPECT_GT(coverage.lookedAtCells(), 0.9 * free_cells);
  // Into each patch and round: about 800 m2 in fewer than 30 stops.
  EXPECT_LT(search.goals, 30);
  EXPECT_LT(search.travelled, 300.0);
}

// A goal beside a house's closed wall has the house's floor within range
// but hidden by that wall: by default the floor stays to be looked at, and
// is, from the open side. With hidden_near_goal_m short of what hides it,
// it is given up.
TEST(CloseLooks, GroundHiddenFromAGoalStaysOpenUnlessHiddenFartherThanAsked) {
  const auto cells = houseWorld();
  const KnownMap map(cells, 0.5);
  const Point beside_the_west_wall{28, 7};
  const auto visitedFrom = [&](CloseLookCoverage& coverage, Point goal) {
    coverage.look(map, goal.x, goal.y, 0);  // facing the wall
    coverage.visited(map, goal);
  };
  CloseLookParameters none;
  none.hidden_near_goal_m = 0;
  CloseLookCoverage all_given_up(none);
  visitedFrom(all_given_up, beside_the_west_wall);
  EXPECT_FALSE(all_given_up.open(33.1, 6.1)) << "the house's floor, 5 m away behind the wall: given up";

  CloseLookParameters three_metres;
  three_metres.hidden_near_goal_m = 3;
  CloseLookCoverage near_wall(three_metres), farther_off(three_metres);
  visitedFrom(near_wall, beside_the_west_wall);
  EXPECT_FALSE(near_wall.open(28.6, 7.1)) << "in view, in front of the wall";
  EXPECT_FALSE(near_wall.open(27.1, 6.1)) << "behind the goal, within the visited radius";
  EXPECT_TRUE(near_wall.open(26.1, 9.1)) << "behind the goal, farther";
  EXPECT_TRUE(near_wall.open(33.1, 6.1)) << "hidden by the wall 2 m from the goal: open";
  EXPECT_TRUE(near_wall.open(35.1, 9.1));
  visitedFrom(farther_off, {24, 7});
  EXPECT_FALSE(farther_off.open(31.1, 6.1)) << "hidden by the wall 6 m from the goal: given up";
  EXPECT_FALSE(farther_off.open(33.1, 6.1));

  // By default nothing is given up for being hidden: the floor is looked at
  // in the end, and looking at it again from its open side marks nothing new.
  CloseLookCoverage coverage;
  visitedFrom(coverage, beside_the_west_wall);
  EXPECT_TRUE(coverage.open(33.1, 6.1));
  searchTheGround(map, coverage, beside_the_west_wall);
  const int looked = coverage.lookedAtCells();
  for (const double gaze : {-60.0, -90.0, -120.0}) coverage.look(map, 33, 9.5, gaze);
  EXPECT_FALSE(coverage.open(33.1, 6.1));
  EXPECT_EQ(coverage.lookedAtCells(), looked);
}

TEST(CloseLooks, OffTheSearchHasNoGoal) {
  const auto cells = houseWorld();
  const KnownMap map(cells, 0.5);
  CloseLookParameters parameters;
  parameters.enabled = false;
  CloseLookCoverage coverage(parameters);
  coverage.look(map, 3, 10, 0);
  EXPECT_EQ(coverage.lookedAtCells(), 0);
  EXPECT_FALSE(coverage.cheapestPatch(map, TravelField(map, 3, 10, 0.6), {3, 10}).has_value());
}

// The explorer on a map with no frontier: it looks closely before it stops.
class CloseLookRun : public ExplorerRun {
 protected:
  void SetUp() override {
    ExplorerRun::SetUp();
    parameters = ExplorerParameters{};
    parameters.look_around = false;
    explorer = Explorer(parameters);
    observation.robot_x = 3;
    observation.robot_y = 10;
    observation.duration = 10000;
    setMap(houseWorld());
  }
  // Ticks until a goto is pushed, then stands the robot at its goal and ends
  // its sub-tasks: a robot that gets wherever it is sent. The decision of
  // the tick that pushed it, or the stop.
  Decision goToNext() {
    for (int i = 0; i < 40; ++i) {
      Decision d = tick();
      if (d.stop) return d;
      for (const auto& push : pushesOf(d))
        if (push.kind == "goto") {
          goals.push_back({push.x, push.y});
          observation.robot_x = push.x;
          observation.robot_y = push.y;
          observation.robot_yaw = push.yaw;
          stack.completeSubTasks(push.parent);
          return d;
        }
    }
    return {};
  }
  std::vector<Point> goals;
};

TEST_F(CloseLookRun, WithNoFrontierLeftItLooksCloselyAtTheGroundBeforeItStops) {
  Decision d;
  for (int jobs = 0; jobs < 300 && !d.stop; ++jobs) d = goToNext();
  ASSERT_TRUE(d.stop.has_value());
  EXPECT_NE(d.stop->find("no reachable ground left to look at closely"), std::string::npos) << *d.stop;
  EXPECT_GT(goals.size(), 3u);
  // It went into the house, or close enough to see its floor.
  bool near_the_floor = false;
  for (const auto& g : goals) near_the_floor |= std::hypot(g.x - 33, g.y - 7) < 6.0 && g.y > 4;
  EXPECT_TRUE(near_the_floor);
  EXPECT_FALSE(explorer.closeLooks().open(33.1, 6.1));

  // Without close looks, the same map ends the run at once.
  parameters.close_looks.enabled = false;
  explorer = Explorer(parameters);
  observation.robot_x = 3;
  observation.robot_y = 10;
  const Decision at_once = tick();
  ASSERT_TRUE(at_once.stop.has_value());
  EXPECT_EQ(at_once.stop->find("look at closely"), std::string::npos) << *at_once.stop;
}

TEST_F(CloseLookRun, GroundNearerThanTheNextFrontierIsLookedAtFirst) {
  auto cells = makeCells(40, 20, kUnknown);
  fillRect(cells, 0.0, 0.0, 20.0, 20.0, kFree);  // the west half known, the frontier at x = 20
  setMap(cells);
  observation.robot_yaw = 180;  // at (3, 10), facing the world's west edge
  std::vector<std::string> notes;
  size_t first_frontier = 0;
  for (int jobs = 0; jobs < 100 && first_frontier == 0; ++jobs) {
    goToNext();
    for (const auto& push : stack.pushes)
      if (push.parent == 0) notes.push_back(push.note);
    stack.pushes.clear();
    for (size_t i = 0; i < notes.size() && first_frontier == 0; ++i)
      if (notes[i].rfind("explore the frontier", 0) == 0) first_frontier = i + 1;
  }
  ASSERT_FALSE(notes.empty());
  EXPECT_EQ(notes.front().rfind("look closely at the ground", 0), 0u) << notes.front();
  ASSERT_GT(first_frontier, 1u) << "a frontier 17 m away waits for the ground around the robot";
  // The looks before it were all in the known half, and it came once the
  // robot stood nearer to it than to what was left to look at.
  for (size_t i = 0; i + 1 < first_frontier; ++i)
    EXPECT_EQ(notes[i].rfind("look closely at the ground", 0), 0u) << notes[i];
  for (size_t i = 0; i + 1 < first_frontier; ++i) EXPECT_LT(goals[i].x, 20.0);
}

TEST_F(CloseLookRun, AGivenUpHypothesisThatMovedIsTriedAgainBeforeTheRestOfTheGround) {
  parameters.verify_attempts = 1;
  explorer = Explorer(parameters);
  observation.hypotheses = {heardPerson("caller", 12, 15)};
  goToNext();  // to a viewpoint of it
  ASSERT_EQ(stack.pushes.front().kind, "verify");
  stack.pushes.clear();
  goToNext();  // the look failed: given up, and the ground comes next
  ASSERT_TRUE(explorer.givenUp("caller"));
  ASSERT_FALSE(stack.pushes.empty());
  EXPECT_EQ(stack.pushes.front().note.rfind("look closely at the ground", 0), 0u) << stack.pushes.front().note;
  stack.pushes.clear();
  observation.hypotheses[0].x = 25;  // its estimate jumped 13 m
  goToNext();
  ASSERT_FALSE(stack.pushes.empty());
  EXPECT_EQ(stack.pushes.front().kind, "verify") << stack.pushes.front().note;
  EXPECT_EQ(stack.pushes.front().object_id, "caller");
  EXPECT_FALSE(explorer.givenUp("caller"));
}

TEST_F(CloseLookRun, AGlimpsedPossiblePersonInterruptsALookAndIsInspected) {
  goToNext();
  const auto first = stack.pushes.front();
  EXPECT_EQ(first.kind, "explore");
  EXPECT_EQ(explorer.phase(), Explorer::Phase::Explore);
  stack.pushes.clear();
  // Pushed, the robot on its way: something person-like is glimpsed.
  HypothesisView figure;
  figure.object_id = "figure";
  figure.x = observation.robot_x + 4;
  figure.y = observation.robot_y;
  figure.glimpsed = true;
  figure.best_category = "person";
  figure.confidence = figure.person_confidence = 0.52;
  observation.hypotheses = {figure};
  const size_t finishes = stack.finishes.size();
  const Decision d = tick();
  ASSERT_EQ(stack.finishes.size(), finishes + 1);
  EXPECT_NE(stack.finishes.back().reason.find("to inspect"), std::string::npos) << stack.finishes.back().reason;
  const auto pushes = pushesOf(d);
  ASSERT_EQ(pushes.size(), 1u);
  EXPECT_EQ(pushes[0].kind, "verify");
  EXPECT_EQ(pushes[0].object_id, "figure");
}

TEST(ExplorerDeterminism, SameInputsGiveTheSameDecisions) {
  auto run = [] {
    Explorer explorer;
    Observation o;
    o.robot_known = true;
    o.robot_x = 3;
    o.robot_y = 3;
    auto cells = makeCells(20, 20, kUnknown);
    fillRect(cells, 0.0, 0.0, 8.0, 8.0, kFree);
    fillRect(cells, 5.0, 2.0, 5.2, 7.0, kOccupied);
    o.map = std::make_shared<const planners::ObstacleCells>(cells);
    FakeStack stack;
    std::string trace;
    for (int i = 0; i < 40; ++i) {
      o.t = i * 0.1;
      o.stack = stack.entries();
      if (i == 12) o.hypotheses = {HypothesisView{"v", 7, 4, false, true, false, false, false, "person", 0.6, 0.6, 0.8}};
      const Decision d = explorer.step(o);
      stack.apply(d);
      if (i % 4 == 3) stack.completeSubTasks(stack.topComposite());
      for (const auto& r : d.requests)
        trace += r.kind + ":" + std::to_string(r.x) + "," + std::to_string(r.y) + "," + std::to_string(r.yaw) + ";";
    }
    return trace;
  };
  const std::string first = run();
  EXPECT_FALSE(first.empty());
  EXPECT_EQ(first, run());
}

}  // namespace
}  // namespace beft::exploration

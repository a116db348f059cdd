#include "planners/octile_search.hpp"
#include "tests/planners/planner_test_support.hpp"
#include "planners/potential_field_planner.hpp"
#include "planners/synthetic_maps.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <memory>
#include <random>

namespace beft::planners {
namespace {

PlanResult plan(PotentialFieldPlanner& planner, const SyntheticCase& c, size_t query, double radius = 0.0) {
  planner.setup(std::make_shared<PlanningMap>(c.map, radius));
  return planner.solve(c.queries[query].first, c.queries[query].second, Deadline::after(10));
}

TEST(PotentialFields, ObstaclePotentialIsNormalisedAndForcePointsAway) {
  GridMap grid(60, 40);
  grid.fillRect(30, 0, 59, 39);  // right half blocked
  const cv::Mat potential = obstaclePotential(grid, 3.0);
  double lo = 0, hi = 0;
  cv::minMaxLoc(potential, &lo, &hi);
  EXPECT_GE(lo, 0.0);
  EXPECT_DOUBLE_EQ(hi, 1.0);
  EXPECT_LT(potential.at<float>(20, 20), potential.at<float>(20, 28));  // rises toward the obstacle
  const VectorField force = negativeGradient(potential);
  const Point2 f = force.at(cellCentre(27, 20));
  EXPECT_LT(f.x, -0.05);  // pushed away (-x), about 1 / (sigma sqrt(2 pi)) = 0.13 at the edge
  EXPECT_NEAR(f.y, 0.0, 1e-3);
}

// M_P and M_F of a region are those of the whole grid there: a cell's value
// depends only on the obstacles within the blur's reach.
TEST(PotentialFields, ARegionsPotentialAndForceAreTheWholeGridsThere) {
  std::mt19937 rng(8);
  GridMap grid(150, 110);
  for (int i = 0; i < 60; ++i) {
    const int x = static_cast<int>(rng() % 150), y = static_cast<int>(rng() % 110);
    grid.fillRect(x, y, x + static_cast<int>(rng() % 12), y + static_cast<int>(rng() % 12));
  }
  const cv::Rect whole(0, 0, grid.width(), grid.height());
  const cv::Mat potential = obstaclePotential(grid, 3.0);
  const VectorField force = obstacleForce(grid, 3.0, whole);
  for (int trial = 0; trial < 40; ++trial) {
    const int x0 = static_cast<int>(rng() % 140), y0 = static_cast<int>(rng() % 100);
    const cv::Rect region(x0, y0, 1 + static_cast<int>(rng() % (150 - x0)), 1 + static_cast<int>(rng() % (110 - y0)));
    const cv::Mat part = obstaclePotential(grid, 3.0, region);
    const VectorField part_force = obstacleForce(grid, 3.0, region);
    for (int y = region.y; y < region.y + region.height; ++y)
      for (int x = region.x; x < region.x + region.width; ++x) {
        ASSERT_NEAR(part.at<float>(y - region.y, x - region.x), potential.at<float>(y, x), 1e-6) << x << "," << y;
        const Point2 centre = cellCentre(x, y);
        ASSERT_NEAR(part_force.at(centre).x, force.at(centre).x, 1e-6) << x << "," << y;
        ASSERT_NEAR(part_force.at(centre).y, force.at(centre).y, 1e-6) << x << "," << y;
      }
  }
  // The border repels like an obstacle: inward at the edges.
  EXPECT_GT(force.at(cellCentre(0, 55)).x, 0.0);
  EXPECT_LT(force.at(cellCentre(75, 109)).y, 0.0);
}

TEST(PotentialFields, TargetDistancesAreNormalisedAndGeodesicGoesAround) {
  GridMap grid(30, 30);
  grid.fillRect(15, 0, 15, 25);
  const GridCell goal{25, 5};
  const cv::Mat euclidean = euclideanTargetDistance(30, 30, goal);
  EXPECT_FLOAT_EQ(euclidean.at<float>(5, 25), 0.0f);
  double hi = 0;
  cv::minMaxLoc(euclidean, nullptr, &hi);
  EXPECT_DOUBLE_EQ(hi, 1.0);
  cv::Rect region;
  const cv::Mat geodesic = geodesicTargetDistance(grid, goal, {5, 5}, region);
  ASSERT_EQ(region, cv::Rect(0, 0, 30, 30));  // all of it within 1.5 times the start's distance
  EXPECT_TRUE(std::isinf(geodesic.at<float>(10, 15)));  // a wall cell
  // Across the wall from the goal the geodesic distance is far larger.
  EXPECT_GT(geodesic.at<float>(5, 5) / geodesic.at<float>(5, 24), 10.0f);
  EXPECT_LT(euclidean.at<float>(5, 5), 1.0f);
  // Its descent direction at (5, 5) points up, toward the end of the wall.
  const Point2 down = negativeGradientFinite(geodesic).at(cellCentre(5, 5));
  EXPECT_GT(down.y, 0.0);
}

// The geodesic M_D is made and differentiated only where the bounded
// wavefront reached: the same as over the whole grid.
TEST(PotentialFields, TheGeodesicFieldIsWorkedOnlyWhereItIsFinite) {
  std::mt19937 rng(4);
  int regions_smaller = 0;
  for (int trial = 0; trial < 20; ++trial) {
    GridMap grid(160, 120);
    for (int i = 0; i < 40; ++i) {
      const int x = static_cast<int>(rng() % 160), y = static_cast<int>(rng() % 120);
      if (rng() % 2) grid.fillRect(x, y, x + static_cast<int>(rng() % 30), y + 1);
      else grid.fillRect(x, y, x + 1, y + static_cast<int>(rng() % 30));
    }
    const GridCell goal{static_cast<int>(rng() % 160), static_cast<int>(rng() % 120)};
    // Starts from next to the goal to across the grid.
    const int spread = 10 + 15 * trial;
    const GridCell start{std::clamp(goal.x + static_cast<int>(rng() % (2 * spread + 1)) - spread, 0, 159),
                         std::clamp(goal.y + static_cast<int>(rng() % (2 * spread + 1)) - spread, 0, 119)};
    grid.setBlocked(goal.x, goal.y, false);
    cv::Rect region;
    const cv::Mat geodesic = geodesicTargetDistance(grid, goal, start, region);
    ASSERT_FALSE(region.empty());
    ASSERT_EQ(geodesic.size(), region.size());
    // The reference: the bounded octile field over the whole grid, normalised
    // by its largest finite value.
    const auto octile = octileDistanceField(grid, goal, start, kGeodesicSlack, kGeodesicMargin);
    double largest = 0;
    for (double d : octile)
      if (std::isfinite(d)) largest = std::max(largest, d);
    cv::Mat reference(grid.height(), grid.width(), CV_32F);
    for (int y = 0; y < grid.height(); ++y)
      for (int x = 0; x < grid.width(); ++x) {
        const double d = octile[grid.index(x, y)];
        reference.at<float>(y, x) = std::isfinite(d) ? static_cast<float>(d * (1.0 / largest)) : INFINITY;
        const float got = region.contains(cv::Point(x, y)) ? geodesic.at<float>(y - region.y, x - region.x) : INFINITY;
        ASSERT_EQ(got, reference.at<float>(y, x)) << "trial " << trial << " cell " << x << "," << y;
      }
    // M_T of the region alone is M_T of the whole grid, also read between cells.
    const VectorField whole = negativeGradientFinite(reference);
    const VectorField part = negativeGradientFinite(geodesic, region.tl());
    for (int i = 0; i < 4000; ++i) {
      const Point2 p{(rng() % 16000) / 100.0, (rng() % 12000) / 100.0};
      ASSERT_EQ(whole.at(p).x, part.at(p).x) << p.x << "," << p.y;
      ASSERT_EQ(whole.at(p).y, part.at(p).y) << p.x << "," << p.y;
    }
    regions_smaller += region.area() < grid.width() * grid.height() ? 1 : 0;
  }
  EXPECT_GT(regions_smaller, 5);
}

TEST(PotentialFieldPlanner, PaperPlannerGoesAroundASimpleWall) {
  const SyntheticCase wall = simpleWallCase();
  for (size_t q = 0; q < wall.queries.size(); ++q) {
    PotentialFieldPlanner planner;
    const PlanResult r = plan(planner, wall, q);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_EQ(test::findCollision(wall.map, r.raw_path), "");
    EXPECT_EQ(test::findCollision(wall.map, r.path), "");
    EXPECT_DOUBLE_EQ(r.path.back().x, wall.queries[q].second.x);
    EXPECT_GE(planner.statistics().at("arrived"), 20);
    // No longer than 1.3 x the octile optimum.
    const auto best = octileAStar(wall.map, {static_cast<int>(wall.queries[q].first.x), static_cast<int>(wall.queries[q].first.y)},
                                  {static_cast<int>(wall.queries[q].second.x), static_cast<int>(wall.queries[q].second.y)});
    EXPECT_LT(r.length(), 1.3 * best.cost);
  }
}

TEST(PotentialFieldPlanner, GeodesicVariantEscapesTheUTrap) {
  const SyntheticCase trap = uTrapCase();
  PotentialFieldParams params;
  params.target = TargetPotential::Geodesic;
  for (size_t q = 0; q < trap.queries.size(); ++q) {
    PotentialFieldPlanner planner(params);
    const PlanResult r = plan(planner, trap, q);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_EQ(planner.statistics().at("arrived"), 100);  // every particle
    EXPECT_EQ(test::findCollision(trap.map, r.path), "");
  }
}

TEST(PotentialFieldPlanner, PaperPlannerIsTrappedByTheUWithoutNoise) {
  // Pure gradient descent on the paper's field stops at the local minimum
  // in front of the U's bottom.
  const SyntheticCase trap = uTrapCase();
  PotentialFieldParams params;
  params.noise = 0;
  PotentialFieldPlanner planner(params);
  const PlanResult r = plan(planner, trap, 0);
  EXPECT_FALSE(r.success);
  EXPECT_EQ(planner.statistics().at("arrived"), 0);
  EXPECT_NE(r.message.find("no particle reached the goal"), std::string::npos);
  // The particles end inside the U, in front of its bottom.
  const Point2 end = planner.particleTraces().front().back();
  EXPECT_GT(end.x, 20.0);
  EXPECT_LT(end.x, 38.0);
  EXPECT_GT(end.y, 18.0);
  EXPECT_LT(end.y, 46.0);
}

TEST(PotentialFieldPlanner, SameSeedSamePathOtherSeedOtherParticles) {
  const SyntheticCase wall = simpleWallCase();
  PotentialFieldPlanner a, b, c;
  a.setSeed(5);
  b.setSeed(5);
  c.setSeed(6);
  const PlanResult ra = plan(a, wall, 0), rb = plan(b, wall, 0), rc = plan(c, wall, 0);
  ASSERT_TRUE(ra.success && rb.success && rc.success);
  ASSERT_EQ(ra.raw_path.size(), rb.raw_path.size());
  for (size_t i = 0; i < ra.raw_path.size(); ++i) {
    EXPECT_EQ(ra.raw_path[i].x, rb.raw_path[i].x);
    EXPECT_EQ(ra.raw_path[i].y, rb.raw_path[i].y);
  }
  EXPECT_NE(a.particleTraces()[0].size() * 1000 + a.particleTraces()[1].size(),
            c.particleTraces()[0].size() * 1000 + c.particleTraces()[1].size());
}

TEST(PotentialFieldPlanner, ReportsUnreachableGoalsAndPassedDeadlines) {
  GridMap grid(20, 20);
  grid.fillRect(10, 0, 10, 19);  // splits the map
  auto map = std::make_shared<PlanningMap>(grid, 0.0);
  PotentialFieldParams params;
  params.target = TargetPotential::Geodesic;
  PotentialFieldPlanner geodesic(params);
  geodesic.setup(map);
  const PlanResult unreachable = geodesic.solve(cellCentre(3, 3), cellCentre(16, 3), Deadline::after(5));
  EXPECT_FALSE(unreachable.success);
  EXPECT_NE(unreachable.message.find("unreachable"), std::string::npos) << unreachable.message;

  PotentialFieldPlanner paper;
  paper.setup(std::make_shared<PlanningMap>(GridMap(200, 200), 0.0));
  const PlanResult late = paper.solve(cellCentre(3, 3), cellCentre(190, 190), Deadline::after(0));
  EXPECT_FALSE(late.success);
  EXPECT_NE(late.message.find("deadline"), std::string::npos) << late.message;
}

TEST(PotentialFieldPlanner, StartOrGoalInAnObstacleIsAFailureNotACrash) {
  const SyntheticCase wall = simpleWallCase();
  PotentialFieldPlanner planner;
  planner.setup(std::make_shared<PlanningMap>(wall.map, 0.0));
  const PlanResult r = planner.solve(cellCentre(20, 10), cellCentre(30, 10), Deadline::after(1));
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("start"), std::string::npos);
  const PlanResult outside = planner.solve(cellCentre(2, 2), {55.0, 3.0}, Deadline::after(1));
  EXPECT_FALSE(outside.success);
  EXPECT_NE(outside.message.find("outside"), std::string::npos);
}

TEST(PotentialFieldParams, SetsByNameAndRefusesNonsense) {
  PotentialFieldParams p;
  p.set("particles", "20");
  p.set("sigma", "2.5");
  p.set("target", "geodesic");
  EXPECT_EQ(p.particles, 20);
  EXPECT_DOUBLE_EQ(p.sigma, 2.5);
  EXPECT_EQ(p.target, TargetPotential::Geodesic);
  EXPECT_THROW(p.set("particles", "0"), std::invalid_argument);
  EXPECT_THROW(p.set("particles", "2.5"), std::invalid_argument);
  EXPECT_THROW(p.set("sigma", "abc"), std::invalid_argument);
  EXPECT_THROW(p.set("step", "3"), std::invalid_argument);
  EXPECT_THROW(p.set("nonsense", "1"), std::invalid_argument);
  EXPECT_THROW(p.set("target", "manhattan"), std::invalid_argument);
}


TEST(PotentialFieldParams, ThePapersOpenConstantsHaveTheirDefaults) {
  const PotentialFieldParams p;
  EXPECT_EQ(p.particles, 100);
  EXPECT_DOUBLE_EQ(p.sigma, 3.0);
  EXPECT_DOUBLE_EQ(p.noise, 2.0);
  EXPECT_DOUBLE_EQ(p.noise_decay, 100.0);
  EXPECT_DOUBLE_EQ(p.step, 1.0);
  EXPECT_DOUBLE_EQ(p.target_weight, 1.0);
  EXPECT_DOUBLE_EQ(p.obstacle_weight, 2.0);
  EXPECT_DOUBLE_EQ(p.straightness_weight, 2.0);
  // --help shows the same defaults.
  const auto names = PotentialFieldParams::names();
  for (const char* expected : {"sigma=3", "noise=2", "noise_decay=100", "straightness_weight=2", "particles=100"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
}

TEST(PotentialFieldPlanner, TheRandomComponentDecaysByOneOverEEveryHundredCells) {
  PotentialFieldParams p;
  EXPECT_DOUBLE_EQ(noiseRms(p, 0), 2.0);
  EXPECT_NEAR(noiseRms(p, 100), 2.0 / std::exp(1.0), 1e-12);
  EXPECT_NEAR(noiseRms(p, 300), 2.0 * std::exp(-3.0), 1e-12);
  p.step = 0.5;  // the decay is per cell travelled, not per step
  EXPECT_NEAR(noiseRms(p, 200), 2.0 / std::exp(1.0), 1e-12);
  // Without noise, every particle follows the same field: one trace for all
  // (and, against the wall, all stuck in the same local minimum).
  PotentialFieldParams quiet;
  quiet.noise = 0;
  quiet.particles = 5;
  PotentialFieldPlanner planner(quiet);
  EXPECT_FALSE(plan(planner, simpleWallCase(), 0).success);
  ASSERT_EQ(planner.particleTraces().size(), 5u);
  const Path& first = planner.particleTraces().front();
  ASSERT_GT(first.size(), 2u);
  for (const auto& trace : planner.particleTraces()) {
    ASSERT_EQ(trace.size(), first.size());
    for (size_t i = 0; i < trace.size(); ++i) EXPECT_EQ(distance(trace[i], first[i]), 0.0);
  }
}

TEST(PotentialFieldPlanner, TheWinnerWeighsLengthAgainstStraightness) {
  // Two hand-made particle paths from (0, 0) to (20, 0): a straight one of
  // 20 cells, and one that weaves 0.2 cells either side of it.
  const Path straight = {{0, 0}, {20, 0}};
  Path weaving{{0, 0}};
  for (int i = 1; i <= 10; ++i) weaving.push_back({2.0 * i - 1, i % 2 ? 0.2 : -0.2});
  // (Weaving is longer; the weights decide how much its turning adds.)
  weaving.push_back({20, 0});
  const double length_straight = pathLength(straight), length_weaving = pathLength(weaving);
  ASSERT_GT(length_weaving, length_straight);
  // With the paper's straightness weight 2 the straight path wins by more than its length.
  EXPECT_LT(particleCost(straight, 2.0), particleCost(weaving, 2.0));
  EXPECT_NEAR(particleCost(straight, 2.0), 20.0, 1e-9);
  EXPECT_GT(particleCost(weaving, 2.0) - particleCost(weaving, 0.0), 1.0);
  // A detour that is straight but long loses to a slightly bent short one.
  const Path detour = {{0, 0}, {0, 10}, {20, 10}, {20, 0}};
  const Path bent = {{0, 0}, {10, 1}, {20, 0}};
  EXPECT_LT(particleCost(bent, 2.0), particleCost(detour, 2.0));
  EXPECT_NEAR(particleCost(bent, 0.0), pathLength(bent), 1e-12);
}

}  // namespace
}  // namespace beft::planners

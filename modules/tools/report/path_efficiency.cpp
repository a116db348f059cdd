#include "tools/report/path_efficiency.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "experts/exploration/known_map.hpp"
#include "experts/exploration/viewpoints.hpp"
#include "planners/astar_planner.hpp"
#include "planners/bench/scenario_raster.hpp"
#include "planners/planning_map.hpp"

namespace beft::report {
namespace {

constexpr double kPlanningSeconds = 10;  // per person; A* on a district's map takes well under a second

// The scenario's obstacle map as the exploration expert reads a known map:
// occupied where an object stands, free elsewhere (nothing unknown).
planners::ObstacleCells groundTruthCells(const planners::ScenarioMap& raster) {
  planners::ObstacleCells cells;
  cells.width = raster.grid.width();
  cells.height = raster.grid.height();
  cells.resolution = raster.resolution;
  cells.cells.resize(static_cast<size_t>(cells.width) * cells.height);
  for (int y = 0; y < cells.height; ++y)
    for (int x = 0; x < cells.width; ++x)
      cells.cells[static_cast<size_t>(y) * cells.width + x] =
          raster.grid.blocked(x, y) ? obstacle_map_t::CELL_OCCUPIED : obstacle_map_t::CELL_FREE;
  return cells;
}

// The robot's state when the person was found: the last one up to that time.
const RobotSample* robotWhenFound(const RunRecord& record, double found_at_s) {
  const auto after = std::upper_bound(record.robot.begin(), record.robot.end(), found_at_s + 1e-9,
                                      [](double t, const RobotSample& s) { return t < s.t; });
  return after == record.robot.begin() ? nullptr : &*std::prev(after);
}

// Where the person truly was at that tick; its last known position otherwise.
std::pair<double, double> personWhenFound(const RunRecord& record, const scenario::Scenario& scenario,
                                          const std::string& id, const RobotSample* when) {
  if (when != nullptr)
    if (const auto then = record.truthAt(id, when->tick)) return {then->x, then->y};
  for (const auto& object : record.truth)
    if (object.id == id) return {object.x, object.y};
  for (const auto& object : scenario.objects)
    if (object.id == id) return {object.x, object.y};
  return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
}

// How far the person's own footprint reaches from its centre [m] (0 if unknown).
double footprintReach(const scenario::Scenario& scenario, const std::string& id) {
  for (const auto& object : scenario.objects) {
    if (object.id != id || !object.visual) continue;
    const auto& v = *object.visual;
    return v.shape == scenario::Visual::Shape::Cylinder ? v.radius : 0.5 * std::hypot(v.size_x, v.size_y);
  }
  return 0;
}

// Any distance within the camera's range, the cheapest by travel alone; the
// person's own cells do not hide it.
exploration::ViewpointParameters viewpointsOf(const scenario::Scenario& scenario, const std::string& id) {
  exploration::ViewpointParameters parameters;
  parameters.min_distance_m = 0;
  parameters.max_distance_m = scenario.robot.camera.range;
  parameters.distance_cost = 0;
  parameters.unknown_cost = 0;
  parameters.target_clearance_m =
      std::max(parameters.target_clearance_m, footprintReach(scenario, id) + scenario.world.resolution);
  return parameters;
}

// The ground truth once: where the robot may stand and how far each cell is
// from the start (the nearest viewpoint), and the planners' map for A*.
struct GroundTruth {
  GroundTruth(const scenario::Scenario& scenario, double start_x, double start_y, double inflation_m)
      : raster(planners::rasterizeScenario(scenario)),
        known(groundTruthCells(raster), inflation_m),
        travel(known, start_x, start_y, inflation_m),
        start{start_x / raster.resolution, start_y / raster.resolution} {
    astar.setup(std::make_shared<const planners::PlanningMap>(raster.grid, inflation_m / raster.resolution));
  }

  // The A* path's length to the viewpoint [m]: octile A*, pulled taut as the
  // planners return every path; the travel over cells if A* finds none.
  double shortestTo(const exploration::Viewpoint& viewpoint) {
    const planners::Point2 goal{viewpoint.x / raster.resolution, viewpoint.y / raster.resolution};
    const planners::PlanResult plan = astar.solve(start, goal, planners::Deadline::after(kPlanningSeconds));
    return plan.success ? std::min(plan.length() * raster.resolution, viewpoint.travel_m) : viewpoint.travel_m;
  }

  planners::ScenarioMap raster;
  exploration::KnownMap known;
  exploration::TravelField travel;
  planners::Point2 start;  // [cells]
  planners::AStarPlanner astar;
};

// The victims' l, p and efficiency; their sum over the victims that have one.
struct Tally {
  double sum = 0;
  int unreachable = 0;
};

void scoreVictim(const RunRecord& record, const scenario::Scenario& scenario, GroundTruth& truth,
                 VictimEntry& victim, Tally& tally) {
  const RobotSample* when = robotWhenFound(record, victim.found_at_s);
  victim.driven_m = when != nullptr ? when->path_length : 0.0;
  const auto [x, y] = personWhenFound(record, scenario, victim.object, when);
  const auto viewpoint = std::isfinite(x) ? exploration::chooseViewpoint(truth.known, truth.travel, x, y, {},
                                                                         viewpointsOf(scenario, victim.object))
                                          : std::nullopt;
  if (!viewpoint) {
    ++tally.unreachable;
    return;
  }
  victim.shortest_path_m = viewpoint->travel_m > 0 ? truth.shortestTo(*viewpoint) : 0.0;
  victim.path_efficiency = pathEfficiency(*victim.shortest_path_m, *victim.driven_m);
  tally.sum += *victim.path_efficiency;
}

}  // namespace

double pathEfficiency(double shortest_m, double driven_m) {
  const double longer = std::max(shortest_m, driven_m);
  return longer > 0 ? shortest_m / longer : 1.0;
}

void scorePathEfficiency(const RunRecord& record, const scenario::Scenario& scenario,
                         const PathEfficiencyOptions& options, RunReport& report) {
  const double start_x = record.robot.empty() ? scenario.robot.x : record.robot.front().x;
  const double start_y = record.robot.empty() ? scenario.robot.y : record.robot.front().y;
  GroundTruth truth(scenario, start_x, start_y, options.inflation_m);
  Tally tally;
  for (auto& victim : report.victims) scoreVictim(record, scenario, truth, victim, tally);
  // Missed persons count 0; a person no robot could reach a viewpoint of, not at all.
  const int counted = report.persons - tally.unreachable;
  report.path_efficiency_mean = counted > 0 ? tally.sum / counted : 0.0;
}

}  // namespace beft::report

#include "services/planner/planner_service.hpp"

#include "planners/path_tools.hpp"
#include "planners/planner_factory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace beft::planner_service {

namespace bp = beft::planners;

namespace {

constexpr size_t kRememberedIds = 100000;
constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

bool finite(const beft::plan_request_t& r) {
  for (double v : {r.start_x, r.start_y, r.start_yaw, r.goal_x, r.goal_y, r.goal_yaw}) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

// The free (inflated) cell centre nearest to p within max_distance cells, if any.
std::optional<bp::Point2> nearestFreeCell(const bp::PlanningMap& map, bp::Point2 p, double max_distance) {
  const int reach = static_cast<int>(std::ceil(max_distance)) + 1;
  const int cx = static_cast<int>(std::floor(p.x));
  const int cy = static_cast<int>(std::floor(p.y));
  std::optional<bp::Point2> best;
  double best_distance = max_distance;
  for (int y = cy - reach; y <= cy + reach; ++y) {
    for (int x = cx - reach; x <= cx + reach; ++x) {
      if (map.inflated().blocked(x, y)) continue;
      const double d = bp::distance(p, bp::cellCentre(x, y));
      if (d <= best_distance) {
        best_distance = d;
        best = bp::cellCentre(x, y);
      }
    }
  }
  return best;
}

std::string describe(double x, double y) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.2f, %.2f)", x, y);
  return text;
}

}  // namespace

PlannerService::PlannerService(ServiceConfig config) : config_(std::move(config)) {
  if (!(config_.robot_radius >= 0)) throw std::invalid_argument("robot radius must be >= 0");
  if (!(config_.default_budget > 0)) throw std::invalid_argument("default time budget must be > 0");
  if (!(config_.goal_snap >= 0)) throw std::invalid_argument("goal snap distance must be >= 0");
  plannerFor(config_.default_planner);  // refuses unknown names and bad parameters now
}

void PlannerService::setObstacleMap(const beft::obstacle_map_t& message) {
  setObstacleMap(bp::decodeObstacleMap(message));
}

void PlannerService::setObstacleMap(const bp::ObstacleCells& map) {
  setObstacleMap(std::make_shared<const bp::ObstacleCells>(map));
}

void PlannerService::setObstacleMap(std::shared_ptr<const bp::ObstacleCells> cells) {
  if (cells == nullptr) return;
  const bool same = cells_ && cells_->width == cells->width && cells_->height == cells->height &&
                    cells_->resolution == cells->resolution && cells_->origin_x == cells->origin_x &&
                    cells_->origin_y == cells->origin_y && cells_->cells == cells->cells;
  if (same) return;  // republished unchanged: keep the prepared planners
  cells_ = std::move(cells);
  ++map_version_;
}

std::shared_ptr<const bp::PlanningMap> PlannerService::planningMap() {
  if (planning_map_version_ != map_version_) {
    // Unknown counts as free: the map holds the obstacles seen so far.
    std::vector<uint8_t> occupied(cells_->cells.size());
    std::transform(cells_->cells.begin(), cells_->cells.end(), occupied.begin(),
                   [](uint8_t cell) { return cell == beft::obstacle_map_t::CELL_OCCUPIED ? 1 : 0; });
    bp::GridMap grid(cells_->width, cells_->height, std::move(occupied));
    // Inflated again only around what changed since the map planned on last.
    const double radius_cells = config_.robot_radius / cells_->resolution;
    planning_map_ = planning_map_ ? std::make_shared<bp::PlanningMap>(std::move(grid), radius_cells, *planning_map_)
                                  : std::make_shared<bp::PlanningMap>(std::move(grid), radius_cells);
    planning_map_version_ = map_version_;
  }
  return planning_map_;
}

bp::Planner& PlannerService::plannerFor(const std::string& name) {
  auto it = planners_.find(name);
  if (it == planners_.end()) {
    bp::PlannerConfig planner_config;
    planner_config.seed = config_.seed;
    planner_config.pf_params = config_.pf_params;
    it = planners_.emplace(name, CachedPlanner{bp::makePlanner(name, planner_config), -1}).first;
  }
  return *it->second.planner;
}

bool PlannerService::remember(int64_t request_id) {
  if (!answered_.insert(request_id).second) return false;
  answered_order_.push_back(request_id);
  if (answered_order_.size() > kRememberedIds) {
    answered_.erase(answered_order_.front());
    answered_order_.pop_front();
  }
  return true;
}

std::optional<beft::plan_result_t> PlannerService::handle(const beft::plan_request_t& request, int64_t utime_now) {
  if (!remember(request.request_id)) return std::nullopt;
  beft::plan_result_t result = plan(request);
  result.utime = utime_now;
  result.request_id = request.request_id;
  result.num_waypoints = static_cast<int32_t>(result.waypoints.size());
  return result;
}

namespace {

beft::waypoint_t waypoint(double x, double y, double yaw_deg) {
  beft::waypoint_t w;
  w.x = x;
  w.y = y;
  w.yaw = yaw_deg;
  return w;
}

// Without a map nothing is known to be in the way: the straight line.
void straightLine(const beft::plan_request_t& request, beft::plan_result_t& result) {
  const double heading = std::atan2(request.goal_y - request.start_y, request.goal_x - request.start_x) * kRadToDeg;
  result.waypoints = {waypoint(request.start_x, request.start_y, heading),
                      waypoint(request.goal_x, request.goal_y, request.goal_yaw)};
  result.success = true;
  result.length = std::hypot(request.goal_x - request.start_x, request.goal_y - request.start_y);
  result.message = "no obstacle map received yet: straight line";
}

}  // namespace

std::string PlannerService::placeEndpoints(const beft::plan_request_t& request, const bp::PlanningMap& map,
                                           Endpoints& cells, std::string& notes) const {
  const double res = cells_->resolution;
  const auto to_cells = [&](double x, double y) {
    return bp::Point2{(x - cells_->origin_x) / res, (y - cells_->origin_y) / res};
  };
  const auto inside = [&](bp::Point2 c) { return c.x >= 0 && c.y >= 0 && c.x < map.width() && c.y < map.height(); };
  cells.start_true = to_cells(request.start_x, request.start_y);
  const bp::Point2 goal_true = to_cells(request.goal_x, request.goal_y);
  if (!inside(cells.start_true)) return "start " + describe(request.start_x, request.start_y) + " is outside the obstacle map";
  if (!inside(goal_true)) return "goal " + describe(request.goal_x, request.goal_y) + " is outside the obstacle map";
  cells.start = cells.start_true;
  if (!map.pointFree(cells.start)) {
    const auto moved = nearestFreeCell(map, cells.start, map.robotRadius() + 2.0);
    if (!moved) return "start " + describe(request.start_x, request.start_y) + " is enclosed by obstacles";
    cells.start = *moved;
    notes += "start within the robot radius of an obstacle: path begins by moving clear; ";
  }
  cells.goal = goal_true;
  if (!map.pointFree(cells.goal)) {
    const auto moved = nearestFreeCell(map, cells.goal, config_.goal_snap / res);
    if (!moved)
      return "goal " + describe(request.goal_x, request.goal_y) +
             " is blocked (within the robot radius of an obstacle) and no free cell lies within " +
             std::to_string(config_.goal_snap) + " m";
    cells.goal = *moved;
    notes += "goal blocked: moved to the nearest free cell; ";
  }
  return "";
}

void PlannerService::toWaypoints(const beft::plan_request_t& request, bp::Path cells_path, const Endpoints& cells,
                                 beft::plan_result_t& result) const {
  const double res = cells_->resolution;
  if (bp::distance(cells.start, cells.start_true) > 1e-9) cells_path.insert(cells_path.begin(), cells.start_true);
  const std::vector<double> headings = bp::travelHeadings(cells_path, 0.0);
  for (size_t i = 0; i < cells_path.size(); ++i) {
    const double yaw = i + 1 == cells_path.size() ? request.goal_yaw : headings[i] * kRadToDeg;
    result.waypoints.push_back(
        waypoint(cells_->origin_x + cells_path[i].x * res, cells_->origin_y + cells_path[i].y * res, yaw));
  }
  result.length = bp::pathLength(cells_path) * res;
}

beft::plan_result_t PlannerService::plan(const beft::plan_request_t& request) {
  beft::plan_result_t result{};
  result.success = false;
  result.length = 0;
  result.planning_time = 0;
  result.planner = request.planner.empty() ? config_.default_planner : request.planner;
  const auto fail = [&result](const std::string& why) {
    result.success = false;
    result.message = why;
    result.waypoints.clear();
    return result;
  };
  if (!finite(request)) return fail("request has a non-finite coordinate or heading");
  bp::Planner* planner = nullptr;
  try {
    planner = &plannerFor(result.planner);
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  double budget = request.time_budget;
  if (!(budget > 0) || !std::isfinite(budget)) budget = config_.default_budget;
  budget = std::min(budget, config_.max_budget);
  if (!hasMap()) {
    straightLine(request, result);
    return result;
  }
  const auto map = planningMap();
  Endpoints cells;
  std::string notes;
  if (const std::string why = placeEndpoints(request, *map, cells, notes); !why.empty()) return fail(why);

  CachedPlanner& cached = planners_.at(result.planner);
  if (cached.map_version != map_version_) {
    planner->setup(map);
    cached.map_version = map_version_;
  }
  planner->setSeed(config_.seed + static_cast<uint64_t>(request.request_id));
  const bool stops_on_time = config_.wall_clock_deadline || result.planner.rfind("ompl:", 0) == 0;
  const bp::PlanResult planned =
      planner->solve(cells.start, cells.goal, stops_on_time ? bp::Deadline::after(budget) : bp::Deadline::never());
  result.planning_time = planned.planning_time_s;
  if (!planned.success) return fail(planned.message);
  toWaypoints(request, planned.path, cells, result);
  result.success = true;
  if (!notes.empty()) result.message = notes.substr(0, notes.size() - 2);
  return result;
}

}  // namespace beft::planner_service

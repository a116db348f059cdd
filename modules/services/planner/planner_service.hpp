// The planner service's logic, free of LCM: keeps the newest obstacle map and
// answers plan requests in world metres. The process (main.cpp) only moves
// messages between LCM and this class.
//
// - The map is what the camera has seen so far: unknown cells count as free.
//   Obstacles are inflated by the robot radius. Until a map arrives, a request
//   gets the straight line (nothing seen, nothing in the way).
// - Each request_id is answered once; a repeated id is ignored.
// - A start within the robot radius of an obstacle (the robot stands close to
//   something it has just seen) is moved to the nearest free cell within
//   radius + 2 cells, and the path begins with that short move. A blocked goal
//   is moved to the nearest free cell within goal_snap metres, or refused.
// - Waypoints are sparse: the planner's path pulled taut on the inflated map
//   (tightenPath). Each carries the heading of travel out of it, the last one
//   the goal heading.
#pragma once

#include "lib/wire/obstacle_map_codec.hpp"
#include "planners/planner.hpp"

#include <beft/obstacle_map_t.hpp>
#include <beft/plan_request_t.hpp>
#include <beft/plan_result_t.hpp>

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace beft::planner_service {

struct ServiceConfig {
  std::string default_planner = "pf";  // planner for requests that name none
  double robot_radius = 0.35;          // obstacle inflation [m]
  double default_budget = 1.0;         // deadline for requests without one [s]
  double max_budget = 30.0;            // longest deadline granted [s]
  double goal_snap = 0.5;              // how far a blocked goal may move [m]
  uint64_t seed = 1;                   // randomised planners use seed + request_id
  // The time budget cuts the grid planners (pf*, astar) too; off by default:
  // they then run to their own bounds, so a plan does not depend on the
  // machine's load (OMPL's planners always stop on the budget).
  bool wall_clock_deadline = false;
  std::vector<std::pair<std::string, std::string>> pf_params;  // potential-field overrides
};

class PlannerService {
 public:
  // Throws std::invalid_argument for an unknown default planner, a bad
  // parameter or a negative radius.
  explicit PlannerService(ServiceConfig config);

  // Keeps the newest map; throws planners::ObstacleMapError when malformed.
  void setObstacleMap(const beft::obstacle_map_t& message);
  void setObstacleMap(const planners::ObstacleCells& cells);
  // The same, shared rather than copied (the map must not change afterwards).
  void setObstacleMap(std::shared_ptr<const planners::ObstacleCells> cells);
  bool hasMap() const { return cells_ != nullptr; }
  int64_t mapVersion() const { return map_version_; }

  // The answer to a request, or nothing when its request_id was answered
  // before. Never throws for bad request contents: they fail with a message.
  std::optional<beft::plan_result_t> handle(const beft::plan_request_t& request, int64_t utime_now);
  // A request answered before this process started (a restart): ignored if it comes again.
  void markAnswered(int64_t request_id) { remember(request_id); }

  const ServiceConfig& config() const { return config_; }

 private:
  struct CachedPlanner {
    std::unique_ptr<planners::Planner> planner;
    int64_t map_version = -1;
  };
  beft::plan_result_t plan(const beft::plan_request_t& request);
  // The request's start and goal in cells: as given, and moved to free cells.
  struct Endpoints {
    planners::Point2 start_true, start, goal;
  };
  // "" when both could be placed, else why not; notes says what was moved.
  std::string placeEndpoints(const beft::plan_request_t& request, const planners::PlanningMap& map, Endpoints& cells,
                             std::string& notes) const;
  void toWaypoints(const beft::plan_request_t& request, planners::Path cells_path, const Endpoints& cells,
                   beft::plan_result_t& result) const;
  std::shared_ptr<const planners::PlanningMap> planningMap();
  planners::Planner& plannerFor(const std::string& name);
  bool remember(int64_t request_id);

  ServiceConfig config_;
  std::shared_ptr<const planners::ObstacleCells> cells_;
  std::shared_ptr<const planners::PlanningMap> planning_map_;
  int64_t map_version_ = 0;
  int64_t planning_map_version_ = -1;
  std::map<std::string, CachedPlanner> planners_;
  std::set<int64_t> answered_;
  std::deque<int64_t> answered_order_;
};

}  // namespace beft::planner_service

// The one interface every planner implements: set up on a map, solve a query
// before a deadline, clear, report statistics. Start and goal checks, timing,
// the collision check of the answer and its shortening to sparse, taut
// waypoints (tightenPath) are done here, identically for every planner.
#pragma once

#include "planners/geometry.hpp"
#include "planners/planning_map.hpp"

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>

namespace beft::planners {

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  static Deadline after(double seconds);
  static Deadline never();
  // The same deadline that also expires when `stop` returns true (e.g. an
  // OMPL termination condition).
  Deadline orWhen(std::function<bool()> stop) const;
  bool expired() const { return Clock::now() >= at_ || (stop_ && stop_()); }
  double remainingSeconds() const;
  Clock::time_point timePoint() const { return at_; }

 private:
  explicit Deadline(Clock::time_point at) : at_(at) {}
  Clock::time_point at_;
  std::function<bool()> stop_;
};

struct PlanResult {
  bool success = false;
  std::string message;      // why it failed, or empty
  Path raw_path;            // the planner's own path
  Path path;                // the sparse, collision-free waypoints returned
  double planning_time_s = 0;  // solve + tightening, wall clock [s]
  double length() const { return pathLength(path); }  // [cells]
};

using Statistics = std::map<std::string, double>;

class Planner {
 public:
  virtual ~Planner() = default;

  virtual std::string name() const = 0;
  // Prepares the planner for a map (per-map work such as potential fields).
  void setup(std::shared_ptr<const PlanningMap> map);
  // Plans from start to goal (continuous cell coordinates). A blocked or
  // outside start or goal is a failure with a message, not an exception.
  PlanResult solve(Point2 start, Point2 goal, const Deadline& deadline);
  // Forgets everything learned from earlier queries (trees, roadmaps).
  virtual void clear() {}
  // True for planners that keep improving their path until the deadline
  // (asymptotically optimal ones): their planning time is the budget.
  virtual bool isAnytime() const { return false; }
  // Seeds the planner's random choices (randomised planners only).
  virtual void setSeed(uint64_t /*seed*/) {}
  // Figures of the last setup and solve: e.g. "setup_ms", "expanded".
  const Statistics& statistics() const { return stats_; }

  // Whether solve() pulls the planner's path taut into sparse waypoints (default on).
  void setTighten(bool enabled) { tighten_ = enabled; }

  const PlanningMap& map() const { return *map_; }
  bool hasMap() const { return map_ != nullptr; }

 protected:
  virtual void setupMap() {}
  // The planner proper: a free path from start to goal (both free), or an
  // empty path and a message in `why_not`.
  virtual Path solvePath(Point2 start, Point2 goal, const Deadline& deadline, std::string& why_not) = 0;

  std::shared_ptr<const PlanningMap> map_;
  Statistics stats_;

 private:
  bool tighten_ = true;
};

}  // namespace beft::planners

#include "planners/planner.hpp"

#include "planners/path_tools.hpp"

#include <stdexcept>

namespace beft::planners {

Deadline Deadline::after(double seconds) {
  const auto span = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  return Deadline(Clock::now() + span);
}

Deadline Deadline::never() { return Deadline(Clock::time_point::max()); }

Deadline Deadline::orWhen(std::function<bool()> stop) const {
  Deadline out = *this;
  out.stop_ = std::move(stop);
  return out;
}

double Deadline::remainingSeconds() const {
  if (at_ == Clock::time_point::max()) return 1e9;
  return std::chrono::duration<double>(at_ - Clock::now()).count();
}

void Planner::setup(std::shared_ptr<const PlanningMap> map) {
  if (!map) throw std::invalid_argument("Planner::setup needs a map");
  map_ = std::move(map);
  stats_.clear();
  const auto begin = Deadline::Clock::now();
  setupMap();
  stats_["setup_ms"] = std::chrono::duration<double, std::milli>(Deadline::Clock::now() - begin).count();
}

PlanResult Planner::solve(Point2 start, Point2 goal, const Deadline& deadline) {
  PlanResult result;
  if (!map_) {
    result.message = "planner " + name() + " has no map (call setup first)";
    return result;
  }
  const auto describe = [](Point2 p) {
    return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
  };
  const auto outside = [this](Point2 p) {
    return !(p.x >= 0 && p.y >= 0 && p.x <= map_->width() && p.y <= map_->height());
  };
  if (outside(start)) { result.message = "start " + describe(start) + " is outside the map"; return result; }
  if (outside(goal)) { result.message = "goal " + describe(goal) + " is outside the map"; return result; }
  if (!map_->pointFree(start)) { result.message = "start " + describe(start) + " is blocked"; return result; }
  if (!map_->pointFree(goal)) { result.message = "goal " + describe(goal) + " is blocked"; return result; }

  const double setup_ms = stats_.count("setup_ms") ? stats_["setup_ms"] : 0.0;
  stats_.clear();
  stats_["setup_ms"] = setup_ms;
  const auto begin = Deadline::Clock::now();
  std::string why_not;
  result.raw_path = solvePath(start, goal, deadline, why_not);
  if (!result.raw_path.empty()) {
    if (!pathFree(*map_, result.raw_path)) {
      result.message = name() + " returned a path that collides with the inflated map";
      result.raw_path.clear();
    } else {
      result.success = true;
      result.path = tighten_ ? tightenPath(*map_, result.raw_path) : removeDuplicatePoints(result.raw_path);
      if (result.path.size() == 1) result.path.push_back(result.path.front());  // start == goal
    }
  } else {
    result.message = why_not.empty() ? name() + " found no path" : why_not;
  }
  result.planning_time_s = std::chrono::duration<double>(Deadline::Clock::now() - begin).count();
  stats_["raw_length"] = pathLength(result.raw_path);
  return result;
}

}  // namespace beft::planners

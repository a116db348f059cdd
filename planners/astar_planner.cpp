#include "planners/astar_planner.hpp"

#include "planners/octile_search.hpp"
#include "planners/path_tools.hpp"

#include <cmath>

namespace beft::planners {

Path AStarPlanner::solvePath(Point2 start, Point2 goal, const Deadline& deadline, std::string& why_not) {
  const GridCell start_cell{static_cast<int>(std::floor(start.x)), static_cast<int>(std::floor(start.y))};
  const GridCell goal_cell{static_cast<int>(std::floor(goal.x)), static_cast<int>(std::floor(goal.y))};
  const OctileSearchResult search = octileAStar(map_->inflated(), start_cell, goal_cell, deadline);
  stats_["expanded"] = static_cast<double>(search.expanded);
  if (!search.found) {
    why_not = deadline.expired() ? "astar: deadline passed" : "astar: goal unreachable";
    return {};
  }
  stats_["octile_cost"] = search.cost;
  Path path{start};
  for (const GridCell& c : search.cells) path.push_back(cellCentre(c.x, c.y));
  path.push_back(goal);
  return removeDuplicatePoints(path);
}

}  // namespace beft::planners

// Octile A* (8-connected, no corner cutting) on the inflated grid: the
// optimal grid baseline. Start and goal are joined to their cells' centres.
#pragma once

#include "planners/planner.hpp"

namespace beft::planners {

class AStarPlanner : public Planner {
 public:
  std::string name() const override { return "astar"; }

 protected:
  Path solvePath(Point2 start, Point2 goal, const Deadline& deadline, std::string& why_not) override;
};

}  // namespace beft::planners

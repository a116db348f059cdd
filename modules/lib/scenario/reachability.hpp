// Which places the robot's footprint can reach from its start pose: a grid
// over the world at its resolution, every cell within `clearance` of a visual
// object's footprint blocked, searched from the robot's start cell.
// Used by the scenario generator (every person reachable) and its tests.
#pragma once

#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"

namespace beft::scenario {

struct ReachabilityOptions {
  double clearance = 0.45;      // robot radius plus a margin [m]
  double reach_distance = 1.0;  // a person counts as reached from within this of its footprint [m]
};

class ReachableSpace {
 public:
  ReachableSpace(const Scenario& scenario, const ReachabilityOptions& options = {});

  // True when some reachable cell lies within reach_distance of the object's
  // footprint (or of its position when it has no visual).
  bool canReach(const Object& object) const;
  bool isReachableAt(double x, double y) const;
  int reachableCells() const { return reachable_cells_; }

 private:
  int cellIndex(double x, double y) const;
  double resolution_;
  int width_ = 0, height_ = 0, reachable_cells_ = 0;
  ReachabilityOptions options_;
  std::vector<char> reachable_;
};

// Ids of the objects labelled person that the robot cannot reach, in file order.
std::vector<std::string> unreachablePersons(const Scenario& scenario,
                                            const ReachabilityOptions& options = {});

}  // namespace beft::scenario

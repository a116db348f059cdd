// The occupied cells of the known map that are a target's own body: a car
// seen whole fills its 4.5 x 1.8 m footprint with occupied cells, and a line
// of sight to its centre that reaches its near side has reached the car, not
// an obstacle in front of it. They are the cells 8-connected to an occupied
// cell within seed_radius of the target's position, no farther than extent
// from it: a wall beside the car, across free space, is not the car's.
#pragma once

#include <cstdint>
#include <vector>

#include "experts/exploration/known_map.hpp"

namespace beft::exploration {

class TargetCells {
 public:
  TargetCells() = default;  // none: every occupied cell blocks
  TargetCells(const KnownMap& map, double x, double y, double seed_radius, double extent);

  bool contains(int x, int y) const;
  std::size_t size() const { return cells_.size(); }

 private:
  int width_ = 0;
  std::vector<int64_t> cells_;  // row * width + column, sorted
};

}  // namespace beft::exploration

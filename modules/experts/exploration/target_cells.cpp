#include "experts/exploration/target_cells.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include <beft/obstacle_map_t.hpp>

namespace beft::exploration {

TargetCells::TargetCells(const KnownMap& map, double x, double y, double seed_radius, double extent)
    : width_(map.width()) {
  const double resolution = map.resolution();
  Cell centre;
  if (!map.cellOf(x, y, centre)) return;
  const int reach = static_cast<int>(std::ceil(extent / resolution));
  const auto within = [&](int cx, int cy, double radius) {
    return map.inside(cx, cy) && std::hypot(map.centreX(cx) - x, map.centreY(cy) - y) <= radius;
  };
  const auto occupied = [&](int cx, int cy) { return map.at(cx, cy) == obstacle_map_t::CELL_OCCUPIED; };
  std::vector<char> taken(static_cast<std::size_t>(2 * reach + 1) * (2 * reach + 1), 0);
  const auto slot = [&](int cx, int cy) {
    return static_cast<std::size_t>(cy - centre.y + reach) * (2 * reach + 1) + (cx - centre.x + reach);
  };
  std::deque<Cell> open;
  const int seed_reach = static_cast<int>(std::ceil(seed_radius / resolution));
  for (int dy = -seed_reach; dy <= seed_reach; ++dy)
    for (int dx = -seed_reach; dx <= seed_reach; ++dx) {
      const int cx = centre.x + dx, cy = centre.y + dy;
      if (std::abs(dx) > reach || std::abs(dy) > reach || !within(cx, cy, seed_radius) || !occupied(cx, cy)) continue;
      taken[slot(cx, cy)] = 1;
      open.push_back({cx, cy});
    }
  while (!open.empty()) {
    const Cell cell = open.front();
    open.pop_front();
    cells_.push_back(static_cast<int64_t>(cell.y) * width_ + cell.x);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int cx = cell.x + dx, cy = cell.y + dy;
        if (std::abs(cx - centre.x) > reach || std::abs(cy - centre.y) > reach) continue;
        if (taken[slot(cx, cy)] || !within(cx, cy, extent) || !occupied(cx, cy)) continue;
        taken[slot(cx, cy)] = 1;
        open.push_back({cx, cy});
      }
  }
  std::sort(cells_.begin(), cells_.end());
}

bool TargetCells::contains(int x, int y) const {
  return std::binary_search(cells_.begin(), cells_.end(), static_cast<int64_t>(y) * width_ + x);
}

}  // namespace beft::exploration

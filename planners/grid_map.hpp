// The occupancy grid every planner plans on: one flag per cell, blocked or
// free. Cells outside the grid count as blocked.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace beft::planners {

class GridMap {
 public:
  GridMap() = default;
  GridMap(int width, int height);  // all cells free
  // From row-major flags, non-zero = blocked (stored as 1).
  GridMap(int width, int height, std::vector<uint8_t> cells);

  int width() const { return width_; }
  int height() const { return height_; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  bool blocked(int x, int y) const { return !inside(x, y) || cells_[index(x, y)] != 0; }
  bool free(int x, int y) const { return !blocked(x, y); }
  void setBlocked(int x, int y, bool blocked = true);
  // Marks the rectangle [x0, x1] x [y0, y1] (inclusive, clipped to the grid).
  void fillRect(int x0, int y0, int x1, int y1, bool blocked = true);

  size_t index(int x, int y) const { return static_cast<size_t>(y) * width_ + x; }
  const std::vector<uint8_t>& cells() const { return cells_; }  // 1 = blocked
  size_t blockedCount() const;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<uint8_t> cells_;
};

// The obstacles grown by a disc of radius_cells: a cell is blocked when some
// point of it lies closer than the radius to some point of a blocked cell. So
// a robot of that radius centred anywhere in a free cell touches no obstacle.
// radius_cells = 0 returns the map unchanged.
GridMap inflate(const GridMap& map, double radius_cells);

// inflate(map, radius_cells), found from an earlier map of the same size and
// its inflation by the same radius: only around the cells that differ is the
// inflation made again (a map grows by a few cells a tick; inflating the
// whole of a 160 x 120 m map was an eighth of a plan's time).
GridMap inflate(const GridMap& map, double radius_cells, const GridMap& earlier, const GridMap& earlier_inflated);

// The smallest rectangle, columns x0 .. x1 of rows y0 .. y1, holding every cell
// in which two row-major grids of width x height cells differ; false (and
// x1 < x0) when none does.
bool differingRectangle(const uint8_t* a, const uint8_t* b, int width, int height, int& x0, int& y0, int& x1,
                        int& y1);

// The same when the caller knows that the map differs from the earlier one at
// most inside columns x0 .. x1 of rows y0 .. y1 (none when x1 < x0).
GridMap inflate(const GridMap& map, double radius_cells, const GridMap& earlier_inflated, int x0, int y0, int x1,
                int y1);

}  // namespace beft::planners

// Test helpers: an independent cell-by-cell collision check (not the
// PlanningMap's row scan), the MovingAI maps of the repository, and small maps.
#pragma once

#include "planners/geometry.hpp"
#include "planners/grid_map.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace beft::planners::test {

// True when the closed segment a-b meets the square [x, x+1] x [y, y+1]
// grown by eps (slab clipping of the segment against the square).
inline bool segmentTouchesCell(Point2 a, Point2 b, int x, int y, double eps = 1e-9) {
  double t0 = 0, t1 = 1;
  const double lo[2] = {x - eps, y - eps};
  const double hi[2] = {x + 1 + eps, y + 1 + eps};
  const double p[2] = {a.x, a.y};
  const double d[2] = {b.x - a.x, b.y - a.y};
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0) {
      if (p[axis] < lo[axis] || p[axis] > hi[axis]) return false;
      continue;
    }
    double ta = (lo[axis] - p[axis]) / d[axis];
    double tb = (hi[axis] - p[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// Every cell of `grid` that a segment of the path touches must be free
// (cells outside the grid count as blocked). Returns "" or what collides.
inline std::string findCollision(const GridMap& grid, const Path& path) {
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Point2 a = path[i], b = path[i + 1];
    const int x0 = static_cast<int>(std::floor(std::min(a.x, b.x))) - 1;
    const int x1 = static_cast<int>(std::floor(std::max(a.x, b.x))) + 1;
    const int y0 = static_cast<int>(std::floor(std::min(a.y, b.y))) - 1;
    const int y1 = static_cast<int>(std::floor(std::max(a.y, b.y))) + 1;
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        if (grid.blocked(x, y) && segmentTouchesCell(a, b, x, y)) {
          return "segment " + std::to_string(i) + " (" + std::to_string(a.x) + ", " + std::to_string(a.y) +
                 ") -> (" + std::to_string(b.x) + ", " + std::to_string(b.y) + ") touches blocked cell (" +
                 std::to_string(x) + ", " + std::to_string(y) + ")";
        }
      }
    }
  }
  return "";
}

// The MovingAI maps kept in the repository (planners/bench/data/movingai).
inline std::string movingAiDir() { return BEFT_MOVINGAI_DIR; }

// One file of that folder. Throws naming the path when it is missing, so a
// test that needs the file fails rather than skipping.
inline std::string movingAiFile(const std::string& name) {
  const std::string path = movingAiDir() + "/" + name;
  if (!std::filesystem::is_regular_file(path)) throw std::runtime_error("missing MovingAI file " + path);
  return path;
}

}  // namespace beft::planners::test

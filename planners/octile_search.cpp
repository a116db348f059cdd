#include "octile_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <queue>

namespace beft::planners {
namespace {

constexpr double kSqrt2 = 1.4142135623730951;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Move {
  int dx, dy;
  double cost;
};
constexpr Move kMoves[8] = {{1, 0, 1.0},  {-1, 0, 1.0}, {0, 1, 1.0},    {0, -1, 1.0},
                            {1, 1, kSqrt2}, {1, -1, kSqrt2}, {-1, 1, kSqrt2}, {-1, -1, kSqrt2}};

// A move is allowed when the target is free and, for a diagonal, both cells
// it passes between are free.
inline bool moveAllowed(const GridMap& grid, int x, int y, const Move& m) {
  if (grid.blocked(x + m.dx, y + m.dy)) return false;
  if (m.dx != 0 && m.dy != 0) return grid.free(x + m.dx, y) && grid.free(x, y + m.dy);
  return true;
}

struct OpenEntry {
  double f;
  double g;
  int32_t index;
  // Lowest f first; among equal f the deepest (largest g) first.
  bool operator<(const OpenEntry& other) const {
    return f != other.f ? f > other.f : g < other.g;
  }
};

}  // namespace

double octileHeuristic(GridCell a, GridCell b) {
  const int dx = std::abs(a.x - b.x);
  const int dy = std::abs(a.y - b.y);
  return (dx + dy) + (kSqrt2 - 2.0) * std::min(dx, dy);
}

OctileSearchResult octileAStar(const GridMap& grid, GridCell start, GridCell goal, const Deadline& deadline) {
  OctileSearchResult result;
  if (grid.blocked(start.x, start.y) || grid.blocked(goal.x, goal.y)) return result;
  const int w = grid.width();
  const size_t n = static_cast<size_t>(w) * grid.height();
  std::vector<double> g(n, kInfinity);
  std::vector<int32_t> parent(n, -1);
  std::vector<uint8_t> closed(n, 0);
  std::priority_queue<OpenEntry> open;
  const int32_t start_index = static_cast<int32_t>(grid.index(start.x, start.y));
  const int32_t goal_index = static_cast<int32_t>(grid.index(goal.x, goal.y));
  g[start_index] = 0;
  open.push({octileHeuristic(start, goal), 0, start_index});
  while (!open.empty()) {
    const OpenEntry top = open.top();
    open.pop();
    if (closed[top.index]) continue;
    closed[top.index] = 1;
    ++result.expanded;
    if (top.index == goal_index) break;
    if ((result.expanded & 4095) == 0 && deadline.expired()) return result;
    const int x = top.index % w;
    const int y = top.index / w;
    for (const Move& m : kMoves) {
      if (!moveAllowed(grid, x, y, m)) continue;
      const int32_t next = static_cast<int32_t>(grid.index(x + m.dx, y + m.dy));
      if (closed[next]) continue;
      const double cost = top.g + m.cost;
      if (cost < g[next]) {
        g[next] = cost;
        parent[next] = top.index;
        open.push({cost + octileHeuristic({x + m.dx, y + m.dy}, goal), cost, next});
      }
    }
  }
  if (!closed[goal_index]) return result;
  result.found = true;
  result.cost = g[goal_index];
  for (int32_t i = goal_index; i != -1; i = parent[i]) result.cells.push_back({i % w, i / w});
  std::reverse(result.cells.begin(), result.cells.end());
  return result;
}

std::vector<double> octileDistanceField(const GridMap& grid, GridCell goal) {
  return octileDistanceField(grid, goal, GridCell{-1, -1}, kInfinity, kInfinity);  // no start: no bound
}

std::vector<double> octileDistanceField(const GridMap& grid, GridCell goal, GridCell start, double slack,
                                        double margin) {
  const int w = grid.width();
  const int h = grid.height();
  std::vector<double> dist(static_cast<size_t>(w) * h, kInfinity);
  if (grid.blocked(goal.x, goal.y)) return dist;
  // The wavefront runs on a copy framed by a ring of blocked cells: no
  // bounds check in the inner loop, and a move is a fixed index offset.
  const int pw = w + 2;
  const size_t padded_cells = static_cast<size_t>(pw) * (h + 2);
  const auto padded = [pw](int x, int y) { return static_cast<int32_t>((y + 1) * pw + x + 1); };
  std::vector<uint8_t> open(padded_cells, 0);  // 1 = free
  const std::vector<uint8_t>& cells = grid.cells();
  for (int y = 0; y < h; ++y) {
    const uint8_t* row = cells.data() + static_cast<size_t>(y) * w;
    uint8_t* out = open.data() + padded(0, y);
    for (int x = 0; x < w; ++x) out[x] = row[x] == 0;
  }
  int32_t offset[8], side_x[8], side_y[8];
  for (int m = 0; m < 8; ++m) {
    offset[m] = kMoves[m].dx + kMoves[m].dy * pw;
    // A diagonal passes between the cells beside it; a straight move checks its target twice.
    side_x[m] = kMoves[m].dy != 0 && kMoves[m].dx != 0 ? kMoves[m].dx : offset[m];
    side_y[m] = kMoves[m].dy != 0 && kMoves[m].dx != 0 ? kMoves[m].dy * pw : offset[m];
  }
  std::vector<double> field(padded_cells, kInfinity);
  // Dial's algorithm: buckets one cell wide. Every step costs at least 1, so
  // expanding bucket k only fills later buckets and the labels in bucket k
  // are final when it is expanded. A label lies within sqrt(2) of its
  // parent's, so a ring of 4 buckets suffices.
  constexpr int kRing = 4;
  std::vector<std::vector<int32_t>> ring(kRing);
  std::vector<uint8_t> done(padded_cells, 0);
  const int32_t goal_index = padded(goal.x, goal.y);
  field[goal_index] = 0;
  ring[0].push_back(goal_index);
  size_t queued = 1;
  const int32_t start_index = grid.inside(start.x, start.y) ? padded(start.x, start.y) : -1;
  double limit = kInfinity;
  for (int64_t k = 0; queued > 0 && k <= limit; ++k) {
    std::vector<int32_t>& bucket = ring[k & (kRing - 1)];
    for (size_t i = 0; i < bucket.size(); ++i) {
      const int32_t index = bucket[i];
      // Skip cells finished already or since moved to an earlier bucket.
      if (done[index] || static_cast<int64_t>(field[index]) != k) continue;
      done[index] = 1;
      if (index == start_index) limit = slack * field[index] + margin;
      for (int m = 0; m < 8; ++m) {
        // Moves are symmetric, so distances to the goal equal distances from it.
        const int32_t next = index + offset[m];
        if (!(open[next] & open[index + side_x[m]] & open[index + side_y[m]])) continue;
        const double cost = field[index] + kMoves[m].cost;
        if (cost < field[next]) {
          field[next] = cost;
          ring[static_cast<int64_t>(cost) & (kRing - 1)].push_back(next);
          ++queued;
        }
      }
    }
    queued -= bucket.size();
    bucket.clear();
  }
  for (int y = 0; y < h; ++y)
    std::copy_n(field.data() + padded(0, y), w, dist.data() + static_cast<size_t>(y) * w);
  return dist;
}

}  // namespace beft::planners

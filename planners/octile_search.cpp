#include "planners/octile_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
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

OctileWavefront::OctileWavefront(GridMap grid, GridCell goal, int reach)
    : grid_(std::move(grid)), goal_(goal), reach_(std::max(reach, 1)) {
  if (grid_.blocked(goal.x, goal.y)) return;  // nothing reachable: exhausted from the start
  startIn(reach_);
}

void OctileWavefront::startIn(int reach) {
  reach_ = reach;
  const auto clip = [](int64_t v, int hi) { return static_cast<int>(std::clamp<int64_t>(v, 0, hi)); };
  window_x_ = clip(int64_t{goal_.x} - reach, grid_.width());
  window_y_ = clip(int64_t{goal_.y} - reach, grid_.height());
  window_width_ = clip(int64_t{goal_.x} + reach + 1, grid_.width()) - window_x_;
  window_height_ = clip(int64_t{goal_.y} + reach + 1, grid_.height()) - window_y_;
  padded_width_ = window_width_ + 2;
  const size_t padded_cells = static_cast<size_t>(padded_width_) * (window_height_ + 2);
  // The wavefront runs on a copy framed by a ring of blocked cells: no bounds
  // check in the inner loop, and a move is a fixed index offset.
  open_.assign(padded_cells, 0);
  field_.assign(padded_cells, kInfinity);
  const std::vector<uint8_t>& cells = grid_.cells();
  for (int y = window_y_; y < window_y_ + window_height_; ++y) {
    const uint8_t* row = cells.data() + grid_.index(window_x_, y);
    uint8_t* out = open_.data() + padded(window_x_, y);
    for (int x = 0; x < window_width_; ++x) out[x] = row[x] == 0 ? kFree : 0;
  }
  // The window's edges that are not the grid's.
  const auto mark_edge = [&](int x, int y) { open_[padded(x, y)] |= open_[padded(x, y)] ? kOnEdge : 0; };
  const int right = window_x_ + window_width_ - 1, bottom = window_y_ + window_height_ - 1;
  for (int y = window_y_; y <= bottom; ++y) {
    if (window_x_ > 0) mark_edge(window_x_, y);
    if (right < grid_.width() - 1) mark_edge(right, y);
  }
  for (int x = window_x_; x <= right; ++x) {
    if (window_y_ > 0) mark_edge(x, window_y_);
    if (bottom < grid_.height() - 1) mark_edge(x, bottom);
  }
  for (auto& bucket : ring_) bucket.clear();
  const int32_t goal_index = padded(goal_.x, goal_.y);
  field_[goal_index] = 0;
  ring_[0].push_back(goal_index);
  queued_ = 1;
  next_bucket_ = 0;
  first_done_ = last_done_ = -1;
}

// Every step costs at least 1, so expanding bucket k only fills later buckets
// and the labels in bucket k are final when it is expanded.
bool OctileWavefront::expandNextBucket() {
  const int64_t k = next_bucket_++;
  std::vector<int32_t>& bucket = ring_[k & (kRing - 1)];
  uint8_t* const open = open_.data();
  double* const field = field_.data();
  const int32_t row = padded_width_;
  for (size_t i = 0; i < bucket.size(); ++i) {
    const int32_t index = bucket[i];
    // Skip cells finished already or since moved to an earlier bucket.
    const uint8_t flags = open[index];
    if ((flags & kDone) || static_cast<int64_t>(field[index]) != k) continue;
    // A path through this cell may leave the window: this window is too small.
    if (flags & kOnEdge) return false;
    open[index] = flags | kDone;
    if (first_done_ < 0 || index < first_done_) first_done_ = index;
    last_done_ = std::max(last_done_, index);
    const double here = field[index];
    // Moves are symmetric, so distances to the goal equal distances from it.
    // Straight moves need their target free; a diagonal also the two cells it
    // passes between (no corner cutting).
    const bool east = open[index + 1] & kFree, west = open[index - 1] & kFree;
    const bool south = open[index + row] & kFree, north = open[index - row] & kFree;
    const auto relax = [&](int32_t next, double cost) {
      if (cost < field[next]) {
        field[next] = cost;
        ring_[static_cast<int64_t>(cost) & (kRing - 1)].push_back(next);
        ++queued_;
      }
    };
    if (east) relax(index + 1, here + 1.0);
    if (west) relax(index - 1, here + 1.0);
    if (south) relax(index + row, here + 1.0);
    if (north) relax(index - row, here + 1.0);
    const double diagonal = here + kSqrt2;
    if (east && south && (open[index + row + 1] & kFree)) relax(index + row + 1, diagonal);
    if (east && north && (open[index - row + 1] & kFree)) relax(index - row + 1, diagonal);
    if (west && south && (open[index + row - 1] & kFree)) relax(index + row - 1, diagonal);
    if (west && north && (open[index - row - 1] & kFree)) relax(index - row - 1, diagonal);
  }
  queued_ -= bucket.size();
  bucket.clear();
  return true;
}

void OctileWavefront::expandOrWiden() {
  if (expandNextBucket()) return;
  startIn(reach_ > std::numeric_limits<int>::max() / 2 ? std::numeric_limits<int>::max() : 2 * reach_);
}

void OctileWavefront::growThroughBucket(int64_t last) {
  // Widening starts over at bucket 0 and comes back this far.
  while (queued_ > 0 && next_bucket_ <= last) expandOrWiden();
}

void OctileWavefront::growUntilFinal(GridCell cell) {
  if (!grid_.inside(cell.x, cell.y)) {
    growThroughBucket(std::numeric_limits<int64_t>::max());  // never reached
    return;
  }
  while (queued_ > 0 && !(inWindow(cell.x, cell.y) && (open_[padded(cell.x, cell.y)] & kDone))) expandOrWiden();
}

void OctileWavefront::growAround(GridCell start, double slack, double margin) {
  growUntilFinal(start);  // unreachable or outside: the whole field
  const double to_start = value(start.x, start.y);
  if (!std::isfinite(to_start) || !isFinal(start.x, start.y)) return;
  const double limit = slack * to_start + margin;
  growThroughBucket(limit >= 9e18 ? std::numeric_limits<int64_t>::max() : static_cast<int64_t>(std::floor(limit)));
}

bool OctileWavefront::finiteBounds(int& x0, int& y0, int& x1, int& y1) const {
  if (first_done_ < 0) return false;
  // Finite values are the finished cells and their neighbours: the rows of
  // the first and last finished cell, and in between each row's first and
  // last finished cell, grown by one.
  const int row_first = first_done_ / padded_width_ - 1 + window_y_;
  const int row_last = last_done_ / padded_width_ - 1 + window_y_;
  int col_first = window_width_, col_last = -1;
  for (int y = row_first; y <= row_last; ++y) {
    const uint8_t* row = open_.data() + padded(window_x_, y);
    const auto finished = [](uint8_t flags) { return (flags & kDone) != 0; };
    const uint8_t* first = std::find_if(row, row + window_width_, finished);
    if (first == row + window_width_) continue;
    const uint8_t* last = std::find_if(std::make_reverse_iterator(row + window_width_), std::make_reverse_iterator(row),
                                       finished).base() - 1;
    col_first = std::min(col_first, static_cast<int>(first - row));
    col_last = std::max(col_last, static_cast<int>(last - row));
  }
  x0 = std::max(0, window_x_ + col_first - 1);
  x1 = std::min(grid_.width() - 1, window_x_ + col_last + 1);
  y0 = std::max(0, row_first - 1);
  y1 = std::min(grid_.height() - 1, row_last + 1);
  return true;
}

bool OctileWavefront::isFinal(int x, int y) const {
  if (!grid_.inside(x, y)) return false;
  if (queued_ == 0) return true;
  return inWindow(x, y) && (open_[padded(x, y)] & kDone) != 0;
}

double OctileWavefront::value(int x, int y) const {
  if (!inWindow(x, y)) return kInfinity;
  return field_[padded(x, y)];
}

void OctileWavefront::rowValues(int y, int x0, int x1, double* out) const {
  if (x1 < x0) return;
  std::fill(out, out + (x1 - x0 + 1), kInfinity);
  if (y < window_y_ || y >= window_y_ + window_height_) return;
  const int from = std::max(x0, window_x_), to = std::min(x1, window_x_ + window_width_ - 1);
  if (from <= to) std::copy_n(field_.data() + padded(from, y), to - from + 1, out + (from - x0));
}

std::vector<double> OctileWavefront::values() const {
  std::vector<double> out(static_cast<size_t>(grid_.width()) * grid_.height(), kInfinity);
  for (int y = window_y_; y < window_y_ + window_height_; ++y)
    std::copy_n(field_.data() + padded(window_x_, y), window_width_, out.data() + grid_.index(window_x_, y));
  return out;
}

std::vector<double> octileDistanceField(const GridMap& grid, GridCell goal) {
  OctileWavefront wavefront(grid, goal);
  wavefront.growThroughBucket(std::numeric_limits<int64_t>::max());
  return wavefront.values();
}

std::vector<double> octileDistanceField(const GridMap& grid, GridCell goal, GridCell start, double slack,
                                        double margin) {
  OctileWavefront wavefront(grid, goal);
  wavefront.growAround(start, slack, margin);
  return wavefront.values();
}

}  // namespace beft::planners

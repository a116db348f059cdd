// Searches over the 8-connected grid of cell centres: orthogonal steps cost 1,
// diagonal steps sqrt(2) and need both orthogonal neighbours free (no corner
// cutting): the rule of MovingAI's octile benchmarks.
#pragma once

#include "planners/grid_map.hpp"
#include "planners/planner.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace beft::planners {

struct GridCell {
  int x = 0;
  int y = 0;
};

struct OctileSearchResult {
  bool found = false;
  double cost = 0;                // octile length of the cell path [cells]
  std::vector<GridCell> cells;    // start cell ... goal cell
  int64_t expanded = 0;           // cells taken off the open list
};

// A* with the octile heuristic (consistent, so the first expansion of the
// goal is optimal). Stops early, with found = false, if the deadline passes.
OctileSearchResult octileAStar(const GridMap& grid, GridCell start, GridCell goal,
                               const Deadline& deadline = Deadline::never());

// Octile distance from every cell to `goal` through free cells (Dijkstra, a
// wavefront with no local minima); +infinity for blocked and unreachable
// cells. Row-major, width * height values.
std::vector<double> octileDistanceField(const GridMap& grid, GridCell goal);

// The same, but only as far as needed around `start`: once the start cell is
// reached at distance D, the wavefront stops at slack * D + margin; farther
// cells stay +infinity. Unreachable start: the whole field.
std::vector<double> octileDistanceField(const GridMap& grid, GridCell goal, GridCell start, double slack,
                                        double margin);

// The wavefront behind octileDistanceField, grown on demand: Dial's algorithm
// with buckets one cell wide, bucket k holding the cells whose distance from
// `goal` lies in [k, k + 1). Growing it bucket by bucket finishes the cells in
// order of distance, so a caller that needs only the near part of the field
// (the cells within some travel, or until one cell is reached) pays for that
// part only; grown to the end it is octileDistanceField.
//
// Its memory, too, covers only a window around the goal: `reach` cells on
// each side at first, twice as many each time a finished cell lies on the
// window's edge (then it starts again in the larger window). Every finished
// cell's shortest path stays inside the window, so the values are those of
// the whole grid.
class OctileWavefront {
 public:
  OctileWavefront(GridMap grid, GridCell goal, int reach = std::numeric_limits<int>::max());

  // Finishes every bucket up to `last`: every cell nearer than last + 1 is final.
  void growThroughBucket(int64_t last);
  // Grows until the cell is final, or to the end when it is unreachable.
  void growUntilFinal(GridCell cell);
  // Grows as far as a path search from `start` needs: once the start is
  // final at distance D, every bucket up to slack * D + margin; the whole
  // field when the start is unreachable.
  void growAround(GridCell start, double slack, double margin);
  bool exhausted() const { return queued_ == 0; }

  bool isFinal(int x, int y) const;
  // The cell's distance [cells]: final once isFinal, else the best found so
  // far (+infinity when none yet).
  double value(int x, int y) const;
  // Every cell's value, row-major.
  std::vector<double> values() const;
  // value(x, y) for x = x0 .. x1 of row y into out[0 .. x1 - x0].
  void rowValues(int y, int x0, int x1, double* out) const;
  // The smallest rectangle, inclusive, outside which every value is still
  // +infinity; false when none is finite.
  bool finiteBounds(int& x0, int& y0, int& x1, int& y1) const;

 private:
  static constexpr int kRing = 4;        // a label lies within sqrt(2) of its parent's
  static constexpr uint8_t kFree = 1;    // open_ flags
  static constexpr uint8_t kOnEdge = 2;  // on the window's edge, inside the grid
  static constexpr uint8_t kDone = 4;    // finished: its value is final
  // Starts over in the window of `reach` cells around the goal.
  void startIn(int reach);
  // False when it finished a cell on the window's edge (start over larger).
  bool expandNextBucket();
  void expandOrWiden();
  bool inWindow(int x, int y) const {
    return x >= window_x_ && y >= window_y_ && x < window_x_ + window_width_ && y < window_y_ + window_height_;
  }
  int32_t padded(int x, int y) const {
    return static_cast<int32_t>((y - window_y_ + 1) * padded_width_ + (x - window_x_) + 1);
  }

  GridMap grid_;
  GridCell goal_;
  int reach_ = 0;
  int window_x_ = 0, window_y_ = 0, window_width_ = 0, window_height_ = 0, padded_width_ = 0;
  std::vector<uint8_t> open_;   // kFree | kOnEdge | kDone; a ring of blocked cells frames the window
  std::vector<double> field_;
  std::vector<int32_t> ring_[kRing];
  size_t queued_ = 0;
  int64_t next_bucket_ = 0;
  int32_t first_done_ = -1, last_done_ = -1;  // lowest and highest padded index finished
};

// Octile distance on an empty grid: the A* heuristic.
double octileHeuristic(GridCell a, GridCell b);

}  // namespace beft::planners

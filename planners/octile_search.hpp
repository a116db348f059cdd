// Searches over the 8-connected grid of cell centres: orthogonal steps cost 1,
// diagonal steps sqrt(2) and need both orthogonal neighbours free (no corner
// cutting): the rule of MovingAI's octile benchmarks.
#pragma once

#include "grid_map.hpp"
#include "planner.hpp"

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

// Octile distance on an empty grid: the A* heuristic.
double octileHeuristic(GridCell a, GridCell b);

}  // namespace beft::planners

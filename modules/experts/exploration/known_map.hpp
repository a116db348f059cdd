// What the robot knows of the world, as the exploration expert uses it: the
// obstacle map M_O (unknown / free / occupied cells), the cells a robot of a
// given radius may stand on (obstacles grown by the radius; unknown counts as
// free, the world's border as a wall), travel distances from the robot over
// those cells, and straight lines of sight.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "planners/grid_map.hpp"
#include "lib/wire/obstacle_map_codec.hpp"
#include "planners/octile_search.hpp"

namespace beft::exploration {

class TargetCells;

struct Cell {
  int x = 0, y = 0;  // column along +x, row along +y
};

// What a straight line from a viewpoint to a target crosses.
struct SightLine {
  bool clear = false;       // no occupied cell on it (away from the target itself)
  double unknown_m = 0;     // length of it through unknown cells [m]
};

class KnownMap {
 public:
  // radius: robot footprint radius plus safety margin [m].
  KnownMap(planners::ObstacleCells cells, double radius);
  // The same, with the map known before (taken over): standing() is then
  // inflated again only around the cells that differ from it.
  KnownMap(planners::ObstacleCells cells, double radius, KnownMap&& earlier);

  int width() const { return cells_.width; }
  int height() const { return cells_.height; }
  double resolution() const { return cells_.resolution; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < cells_.width && y < cells_.height; }
  // CELL_* value; CELL_OCCUPIED outside the map.
  uint8_t at(int x, int y) const;
  bool cellOf(double wx, double wy, Cell& cell) const;  // false outside the map
  double centreX(int x) const { return cells_.origin_x + (x + 0.5) * cells_.resolution; }
  double centreY(int y) const { return cells_.origin_y + (y + 0.5) * cells_.resolution; }

  // The robot may stand with its centre in this cell. Answered from the
  // whole inflated grid once standing() made it, else from the cell's own
  // neighbourhood (the same answer): a map re-checked often and searched
  // rarely is not inflated whole each time it changes.
  bool standable(int x, int y) const;
  // Every cell's answer at once (made on first use: the whole map is inflated).
  const planners::GridMap& standing() const;

  // Straight line from (ax, ay) to (bx, by); occupied cells closer than
  // ignore_near_b to b (the target's own footprint) do not block it, and
  // reaching one of `own` (the target's body, target_cells.hpp) is reaching b.
  SightLine sight(double ax, double ay, double bx, double by, double ignore_near_b,
                  const TargetCells* own = nullptr) const;

 private:
  planners::GridMap inflatedAgain(const planners::GridMap& occupied) const;

  planners::ObstacleCells cells_;
  double radius_cells_ = 0;
  int border_ = 0;                                   // cells along the world's edge that are never standable
  std::vector<std::pair<int, int>> reach_offsets_;   // offsets of occupied cells that forbid standing
  mutable std::optional<planners::GridMap> standing_;  // 1 = the robot's centre may not be here
  // The latest earlier map whose standing() was made, and that grid, until standing() is made.
  mutable std::optional<planners::ObstacleCells> earlier_cells_;
  mutable std::optional<planners::GridMap> earlier_standing_;
};

// Travel distances [m] from the robot to every cell over standable cells
// (8-connected, no corner cutting); +infinity where unreachable. A robot too
// close to an obstacle may still leave: cells within escape_radius of it count
// as standable for this search.
//
// The distances are found outwards from the robot as far as the questions
// asked need: within() looks no farther than its limit, at() as far as the
// cell (the whole reachable map when the cell is unreachable).
class TravelField {
 public:
  TravelField(const KnownMap& map, double robot_x, double robot_y, double escape_radius);
  double at(int x, int y) const;  // +infinity outside or unreachable
  bool reachable(int x, int y) const;
  // at(x, y) when it is at most limit_m, else +infinity.
  double within(int x, int y, double limit_m) const;

 private:
  int width_ = 0, height_ = 0;
  double resolution_ = 0.1;
  // From the robot's cell; none when the robot is off the map.
  mutable std::optional<planners::OctileWavefront> wavefront_;
};

}  // namespace beft::exploration

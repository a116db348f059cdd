// The map representation and validity checker shared by every planner, so
// that comparisons are fair: the raw obstacle grid, the grid inflated by the
// robot's radius, and collision tests of points and straight segments against
// the inflated grid.
//
// A point or segment is free when every cell its closed extent touches (with a
// tolerance of 1e-7 cells) is free. So a diagonal step through a cell corner
// needs all four cells around the corner free (no corner cutting), exactly
// the rule of MovingAI's octile grids, and a path made of free segments keeps
// the robot's disc clear of every obstacle cell.
#pragma once

#include "planners/geometry.hpp"
#include "planners/grid_map.hpp"

#include <opencv2/core.hpp>

#include <mutex>
#include <vector>

namespace beft::planners {

class PlanningMap {
 public:
  PlanningMap(GridMap raw, double robot_radius_cells);
  // The same, inflated from an earlier planning map (of any size and radius:
  // it is used only when both match).
  PlanningMap(GridMap raw, double robot_radius_cells, const PlanningMap& earlier);

  const GridMap& raw() const { return raw_; }
  const GridMap& inflated() const { return inflated_; }
  double robotRadius() const { return radius_; }  // [cells]
  int width() const { return raw_.width(); }
  int height() const { return raw_.height(); }

  bool pointFree(Point2 p) const;
  bool segmentFree(Point2 a, Point2 b) const;
  // The largest t in [0, 1] such that segment a -> a + t (b - a) is free
  // (0 when a itself is blocked), found to within `tolerance` cells.
  double freeFraction(Point2 a, Point2 b, double tolerance = 0.05) const;

  // Distance from p to the nearest raw obstacle cell's square [cells]: the
  // nearest obstacle cells of p's cell and its neighbours come from a
  // labelled distance transform of the raw grid, the distance to each is
  // exact. The map border does not count; a map without obstacles gives a
  // large number.
  // The transform is made on the first call (most planners never ask).
  double clearance(Point2 p) const;

 private:
  void labelNearestObstacles() const;

  GridMap raw_;
  GridMap inflated_;
  double radius_;
  mutable std::once_flag labelled_;
  mutable cv::Mat nearest_label_;                      // CV_32S: label of the nearest obstacle cell
  mutable std::vector<cv::Point> obstacle_of_label_;  // label -> obstacle cell
};

}  // namespace beft::planners

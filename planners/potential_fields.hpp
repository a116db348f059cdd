// The fields of the paper's potential-field planner (section 3.1): M_P, M_F,
// M_D and M_T, as OpenCV matrices over the grid (one value per cell centre).
#pragma once

#include "planners/geometry.hpp"
#include "planners/grid_map.hpp"
#include "planners/octile_search.hpp"

#include <opencv2/core.hpp>

namespace beft::planners {

// A 2-D vector field given at cell centres, read with bilinear interpolation.
class VectorField {
 public:
  VectorField() = default;
  // CV_32F, same size; element (0, 0) is the grid's cell `origin`. Read
  // outside its cells, the field takes its nearest edge's values.
  VectorField(cv::Mat fx, cv::Mat fy, cv::Point origin = cv::Point(0, 0));
  Point2 at(Point2 p) const;
  const cv::Mat& fx() const { return fx_; }
  const cv::Mat& fy() const { return fy_; }
  cv::Point origin() const { return origin_; }

 private:
  cv::Mat fx_, fy_;
  cv::Point origin_;
};

// M_P: the obstacle grid blurred with a Gaussian of `sigma` cells (> 0).
// The kernel sums to 1, so M_P, a weighted mean of 0 / 1 cells, lies in
// [0, 1] as it is: it is not rescaled by its largest value, which keeps
// each cell's value a matter of the obstacles within the blur's reach only.
// Outside the grid counts as obstacle, so the border repels too.
cv::Mat obstaclePotential(const GridMap& grid, double sigma);
// M_P over the cells of `region` only (which may reach beyond the grid):
// element (0, 0) is the region's top-left cell.
cv::Mat obstaclePotential(const GridMap& grid, double sigma, cv::Rect region);

// M_F = -grad M_P over the cells of `region` (3x3 Sobel of M_P, scaled to
// unit spacing), made from the obstacles within the blur's reach of it. The
// potential-field planners ask for the whole grid (the paper's) or for the
// region their geodesic wavefront reached.
VectorField obstacleForce(const GridMap& grid, double sigma, cv::Rect region);

// -grad of a scalar field per cell (3x3 Sobel, scaled to unit spacing). So
// M_F = negativeGradient(M_P) and, for the paper's target, M_T =
// negativeGradient(M_D).
VectorField negativeGradient(const cv::Mat& field);

// M_D of the paper: the distance transform to the goal cell over the whole
// grid (obstacles ignored), normalised to [0, 1].
cv::Mat euclideanTargetDistance(int width, int height, GridCell goal);

// M_D, geodesic variant: the octile distance to the goal through free cells
// (a wavefront, no local minima), normalised to [0, 1]; +infinity on blocked
// and unreachable cells, and beyond kGeodesicSlack times the start's distance
// + kGeodesicMargin cells. Given over `region` only (set to a rectangle of
// the grid whose edge cells and every cell outside are infinite, unless on
// the grid's edge; empty when all are): element (0, 0) is its top-left cell.
constexpr double kGeodesicSlack = 1.5;
constexpr double kGeodesicMargin = 20.0;  // [cells]
cv::Mat geodesicTargetDistance(const GridMap& grid, GridCell goal, GridCell start, cv::Rect& region);

// -grad of a field with infinite cells (the geodesic M_D): central
// differences where both neighbours are finite, one-sided where one is,
// zero where none is or on infinite cells; outside the matrix counts as
// infinite. `origin`: the grid cell of the matrix's element (0, 0).
VectorField negativeGradientFinite(const cv::Mat& field, cv::Point origin = cv::Point(0, 0));

}  // namespace beft::planners

// The fields of the paper's potential-field planner (section 3.1): M_P, M_F,
// M_D and M_T, as OpenCV matrices over the grid (one value per cell centre).
#pragma once

#include "geometry.hpp"
#include "grid_map.hpp"
#include "octile_search.hpp"

#include <opencv2/core.hpp>

namespace beft::planners {

// A 2-D vector field given at cell centres, read with bilinear interpolation.
class VectorField {
 public:
  VectorField() = default;
  VectorField(cv::Mat fx, cv::Mat fy);  // CV_32F, same size
  Point2 at(Point2 p) const;
  const cv::Mat& fx() const { return fx_; }
  const cv::Mat& fy() const { return fy_; }

 private:
  cv::Mat fx_, fy_;
};

// M_P: the obstacle grid blurred with a Gaussian of `sigma` cells and
// normalised to [0, 1]. Outside the grid counts as obstacle, so the border
// repels too. All zero for a map without obstacles.
cv::Mat obstaclePotential(const GridMap& grid, double sigma);

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
// + kGeodesicMargin cells. finite_region, when given, receives a rectangle
// outside which every cell is infinite (empty when all are).
constexpr double kGeodesicSlack = 1.5;
constexpr double kGeodesicMargin = 20.0;  // [cells]
cv::Mat geodesicTargetDistance(const GridMap& grid, GridCell goal, GridCell start, cv::Rect* finite_region = nullptr);

// -grad of a field with infinite cells (the geodesic M_D): central
// differences where both neighbours are finite, one-sided where one is,
// zero where none is or on infinite cells. Only cells inside finite_region
// (every finite cell must be; empty: the whole field) are computed.
VectorField negativeGradientFinite(const cv::Mat& field, cv::Rect finite_region = cv::Rect());

}  // namespace beft::planners

#include "planners/potential_fields.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace beft::planners {

VectorField::VectorField(cv::Mat fx, cv::Mat fy, cv::Point origin)
    : fx_(std::move(fx)), fy_(std::move(fy)), origin_(origin) {}

Point2 VectorField::at(Point2 p) const {
  p = Point2{p.x - origin_.x, p.y - origin_.y};
  const int w = fx_.cols;
  const int h = fx_.rows;
  const double u = std::clamp(p.x - 0.5, 0.0, w - 1.0);
  const double v = std::clamp(p.y - 0.5, 0.0, h - 1.0);
  const int x0 = std::min(static_cast<int>(u), w - 1);
  const int y0 = std::min(static_cast<int>(v), h - 1);
  const int x1 = std::min(x0 + 1, w - 1);
  const int y1 = std::min(y0 + 1, h - 1);
  const double a = u - x0;
  const double b = v - y0;
  const auto lerp = [&](const cv::Mat& m) {
    const float* r0 = m.ptr<float>(y0);
    const float* r1 = m.ptr<float>(y1);
    return (1 - b) * ((1 - a) * r0[x0] + a * r0[x1]) + b * ((1 - a) * r1[x0] + a * r1[x1]);
  };
  return {lerp(fx_), lerp(fy_)};
}

namespace {

// Cells beyond which OpenCV's Gaussian kernel for float images (4 sigma on
// each side) has no weight, plus one.
int blurReach(double sigma) { return (cvRound(sigma * 8 + 1) | 1) / 2 + 1; }

}  // namespace

cv::Mat obstaclePotential(const GridMap& grid, double sigma, cv::Rect region) {
  if (!(sigma > 0)) throw std::invalid_argument("the blur of M_O needs sigma > 0");
  if (region.empty()) return cv::Mat(region.height, region.width, CV_32F);
  const int reach = blurReach(sigma);
  // The region with the blur's reach around it; outside the grid is obstacle.
  const cv::Rect source(region.x - reach, region.y - reach, region.width + 2 * reach, region.height + 2 * reach);
  cv::Mat occupancy(source.size(), CV_32F, cv::Scalar(1.0));
  const cv::Rect inside = source & cv::Rect(0, 0, grid.width(), grid.height());
  if (!inside.empty()) {
    const cv::Mat cells(grid.height(), grid.width(), CV_8U, const_cast<uint8_t*>(grid.cells().data()));
    cells(inside).convertTo(occupancy(inside - source.tl()), CV_32F);  // cells are 0 / 1
  }
  cv::Mat blurred;
  // The copy's own border is farther than the kernel reaches from the region.
  cv::GaussianBlur(occupancy, blurred, cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
  cv::Mat potential = blurred(cv::Rect(reach, reach, region.width, region.height)).clone();
  cv::min(potential, 1.0, potential);  // a kernel summing to 1 within rounding
  return potential;
}

cv::Mat obstaclePotential(const GridMap& grid, double sigma) {
  return obstaclePotential(grid, sigma, cv::Rect(0, 0, grid.width(), grid.height()));
}

VectorField obstacleForce(const GridMap& grid, double sigma, cv::Rect region) {
  // One more cell around for the Sobel operator.
  const cv::Rect around(region.x - 1, region.y - 1, region.width + 2, region.height + 2);
  const VectorField whole = negativeGradient(obstaclePotential(grid, sigma, around));
  const cv::Rect inner(1, 1, region.width, region.height);
  return VectorField(whole.fx()(inner).clone(), whole.fy()(inner).clone(), region.tl());
}

VectorField negativeGradient(const cv::Mat& field) {
  cv::Mat gx, gy;
  // A 3x3 Sobel sums 8 unit differences: scale 1/8 gives the slope per cell.
  cv::Sobel(field, gx, CV_32F, 1, 0, 3, -1.0 / 8.0, 0, cv::BORDER_REPLICATE);
  cv::Sobel(field, gy, CV_32F, 0, 1, 3, -1.0 / 8.0, 0, cv::BORDER_REPLICATE);
  return VectorField(gx, gy);
}

cv::Mat euclideanTargetDistance(int width, int height, GridCell goal) {
  cv::Mat not_goal(height, width, CV_8U, cv::Scalar(255));
  not_goal.at<uint8_t>(goal.y, goal.x) = 0;
  cv::Mat distance;
  cv::distanceTransform(not_goal, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  double max_value = 0;
  cv::minMaxLoc(distance, nullptr, &max_value);
  if (max_value > 0) distance /= max_value;
  return distance;
}

cv::Mat geodesicTargetDistance(const GridMap& grid, GridCell goal, GridCell start, cv::Rect& region) {
  // A window that holds the whole bounded field when the path is at most a
  // third longer than the straight line; it widens by itself when not.
  const double straight = octileHeuristic(goal, start);
  const int reach = static_cast<int>(std::min(1e9, std::ceil(kGeodesicSlack * 1.34 * straight + kGeodesicMargin + 4)));
  OctileWavefront wavefront(grid, goal, reach);
  wavefront.growAround(start, kGeodesicSlack, kGeodesicMargin);
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  if (!wavefront.finiteBounds(x0, y0, x1, y1)) {
    region = cv::Rect();
    return cv::Mat();
  }
  // One more cell around, infinite (or the grid's edge): the gradient and the
  // interpolation between cells read what they would over the whole grid.
  region = cv::Rect(x0 - 1, y0 - 1, x1 - x0 + 3, y1 - y0 + 3) & cv::Rect(0, 0, grid.width(), grid.height());
  // The bounded field, row by row, then scaled by its largest finite value.
  const int width = x1 - x0 + 1;
  std::vector<double> values(static_cast<size_t>(width) * (y1 - y0 + 1));
  double max_value = 0;
  for (int y = y0; y <= y1; ++y) {
    double* row = values.data() + static_cast<size_t>(y - y0) * width;
    wavefront.rowValues(y, x0, x1, row);
    for (int i = 0; i < width; ++i)
      if (std::isfinite(row[i])) max_value = std::max(max_value, row[i]);
  }
  const double scale = max_value > 0 ? 1.0 / max_value : 1.0;
  cv::Mat distance(region.size(), CV_32F, cv::Scalar(std::numeric_limits<float>::infinity()));
  for (int y = y0; y <= y1; ++y) {
    const double* row = values.data() + static_cast<size_t>(y - y0) * width;
    float* out = distance.ptr<float>(y - region.y) + (x0 - region.x);
    for (int i = 0; i < width; ++i)
      if (std::isfinite(row[i])) out[i] = static_cast<float>(row[i] * scale);
  }
  return distance;
}

VectorField negativeGradientFinite(const cv::Mat& field, cv::Point origin) {
  const int w = field.cols;
  const int h = field.rows;
  cv::Mat gx(h, w, CV_32F, cv::Scalar(0));
  cv::Mat gy(h, w, CV_32F, cv::Scalar(0));
  const auto value = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= w || y >= h) return std::numeric_limits<float>::infinity();
    return field.at<float>(y, x);
  };
  const auto slope = [](float before, float here, float after) -> float {
    const bool has_before = std::isfinite(before);
    const bool has_after = std::isfinite(after);
    if (has_before && has_after) return 0.5f * (after - before);
    if (has_after) return after - here;
    if (has_before) return here - before;
    return 0.0f;
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float here = value(x, y);
      if (!std::isfinite(here)) continue;
      gx.at<float>(y, x) = -slope(value(x - 1, y), here, value(x + 1, y));
      gy.at<float>(y, x) = -slope(value(x, y - 1), here, value(x, y + 1));
    }
  }
  return VectorField(gx, gy, origin);
}

}  // namespace beft::planners

#include "potential_fields.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace beft::planners {

VectorField::VectorField(cv::Mat fx, cv::Mat fy) : fx_(std::move(fx)), fy_(std::move(fy)) {}

Point2 VectorField::at(Point2 p) const {
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

cv::Mat obstaclePotential(const GridMap& grid, double sigma) {
  const int w = grid.width();
  const int h = grid.height();
  cv::Mat occupancy;
  cv::Mat(h, w, CV_8U, const_cast<uint8_t*>(grid.cells().data())).convertTo(occupancy, CV_32F);  // cells are 0 / 1
  const int pad = static_cast<int>(std::ceil(3 * sigma)) + 1;
  cv::Mat padded;
  cv::copyMakeBorder(occupancy, padded, pad, pad, pad, pad, cv::BORDER_CONSTANT, cv::Scalar(1.0));
  cv::Mat blurred;
  cv::GaussianBlur(padded, blurred, cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
  cv::Mat potential = blurred(cv::Rect(pad, pad, w, h)).clone();
  double max_value = 0;
  cv::minMaxLoc(potential, nullptr, &max_value);
  if (max_value > 0) potential /= max_value;
  return potential;
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

cv::Mat geodesicTargetDistance(const GridMap& grid, GridCell goal, GridCell start, cv::Rect* finite_region) {
  OctileWavefront wavefront(grid, goal);
  wavefront.growAround(start, kGeodesicSlack, kGeodesicMargin);
  cv::Mat distance(grid.height(), grid.width(), CV_32F, cv::Scalar(std::numeric_limits<float>::infinity()));
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  if (!wavefront.finiteBounds(x0, y0, x1, y1)) {
    if (finite_region) *finite_region = cv::Rect();
    return distance;
  }
  double max_value = 0;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double d = wavefront.value(x, y);
      if (std::isfinite(d)) max_value = std::max(max_value, d);
    }
  const double scale = max_value > 0 ? 1.0 / max_value : 1.0;
  for (int y = y0; y <= y1; ++y) {
    float* row = distance.ptr<float>(y);
    for (int x = x0; x <= x1; ++x) {
      const double d = wavefront.value(x, y);
      if (std::isfinite(d)) row[x] = static_cast<float>(d * scale);
    }
  }
  if (finite_region) *finite_region = cv::Rect(x0, y0, x1 - x0 + 1, y1 - y0 + 1);
  return distance;
}

VectorField negativeGradientFinite(const cv::Mat& field, cv::Rect finite_region) {
  const int w = field.cols;
  const int h = field.rows;
  if (finite_region.empty()) finite_region = cv::Rect(0, 0, w, h);
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
  for (int y = finite_region.y; y < finite_region.y + finite_region.height; ++y) {
    for (int x = finite_region.x; x < finite_region.x + finite_region.width; ++x) {
      const float here = value(x, y);
      if (!std::isfinite(here)) continue;
      gx.at<float>(y, x) = -slope(value(x - 1, y), here, value(x + 1, y));
      gy.at<float>(y, x) = -slope(value(x, y - 1), here, value(x, y + 1));
    }
  }
  return VectorField(gx, gy);
}

}  // namespace beft::planners

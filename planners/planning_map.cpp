#include "planners/planning_map.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace beft::planners {
namespace {

constexpr double kTouchTolerance = 1e-7;  // [cells]

// Columns [first, last] whose closed, slightly grown extent meets [lo, hi].
inline int firstCell(double lo) { return static_cast<int>(std::ceil(lo - 1.0 - kTouchTolerance)); }
inline int lastCell(double hi) { return static_cast<int>(std::floor(hi + kTouchTolerance)); }

}  // namespace

PlanningMap::PlanningMap(GridMap raw, double robot_radius_cells)
    : raw_(std::move(raw)), inflated_(inflate(raw_, robot_radius_cells)), radius_(robot_radius_cells) {}

PlanningMap::PlanningMap(GridMap raw, double robot_radius_cells, const PlanningMap& earlier)
    : raw_(std::move(raw)),
      inflated_(earlier.radius_ == robot_radius_cells
                    ? inflate(raw_, robot_radius_cells, earlier.raw_, earlier.inflated_)
                    : inflate(raw_, robot_radius_cells)),
      radius_(robot_radius_cells) {}

void PlanningMap::labelNearestObstacles() const {
  if (raw_.blockedCount() == 0) return;
  const int w = raw_.width();
  const int h = raw_.height();
  const cv::Mat blocked(h, w, CV_8U, const_cast<uint8_t*>(raw_.cells().data()));
  cv::Mat free_mask;
  cv::compare(blocked, 0, free_mask, cv::CMP_EQ);  // 255 where free
  cv::Mat distance;
  cv::distanceTransform(free_mask, distance, nearest_label_, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
  obstacle_of_label_.assign(raw_.blockedCount() + 1, cv::Point(-1, -1));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (free_mask.at<uint8_t>(y, x) != 0) continue;
      const int label = nearest_label_.at<int>(y, x);
      if (label >= 0 && label < static_cast<int>(obstacle_of_label_.size())) obstacle_of_label_[label] = {x, y};
    }
  }
}

bool PlanningMap::pointFree(Point2 p) const { return segmentFree(p, p); }

bool PlanningMap::segmentFree(Point2 a, Point2 b) const {
  if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) {
    return false;
  }
  const int row_first = firstCell(std::min(a.y, b.y));
  const int row_last = lastCell(std::max(a.y, b.y));
  const int col_min = firstCell(std::min(a.x, b.x));
  const int col_max = lastCell(std::max(a.x, b.x));
  // Short segments (particle steps): when every cell of the bounding box is
  // free, so is every cell the segment touches.
  if (row_last - row_first <= 1 && col_max - col_min <= 1) {
    bool all_free = true;
    for (int row = row_first; row <= row_last && all_free; ++row) {
      for (int col = col_min; col <= col_max; ++col) {
        if (inflated_.blocked(col, row)) {
          all_free = false;
          break;
        }
      }
    }
    if (all_free) return true;
  }
  // Scan the rows the segment touches; in each row, the segment's x-extent
  // within that row's band gives the columns it touches.
  const double dy = b.y - a.y;
  const double dx = b.x - a.x;
  for (int row = row_first; row <= row_last; ++row) {
    double t0 = 0;
    double t1 = 1;
    if (dy != 0) {
      const double ta = (row - kTouchTolerance - a.y) / dy;
      const double tb = (row + 1 + kTouchTolerance - a.y) / dy;
      t0 = std::max(0.0, std::min(ta, tb));
      t1 = std::min(1.0, std::max(ta, tb));
      if (t0 > t1) continue;
    }
    const double xa = a.x + t0 * dx;
    const double xb = a.x + t1 * dx;
    const int col_first = firstCell(std::min(xa, xb));
    const int col_last = lastCell(std::max(xa, xb));
    for (int col = col_first; col <= col_last; ++col) {
      if (inflated_.blocked(col, row)) return false;
    }
  }
  return true;
}

double PlanningMap::freeFraction(Point2 a, Point2 b, double tolerance) const {
  if (segmentFree(a, b)) return 1.0;
  if (!pointFree(a)) return 0.0;
  // Walk forward in small steps to the first blocked sample, then bisect.
  const double length = distance(a, b);
  const int steps = std::max(1, static_cast<int>(std::ceil(length / 0.25)));
  double good = 0;
  double bad = 1;
  for (int i = 1; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    if (!segmentFree(a, a + t * (b - a))) {
      bad = t;
      break;
    }
    good = t;
  }
  while ((bad - good) * length > tolerance) {
    const double mid = 0.5 * (good + bad);
    if (segmentFree(a, a + mid * (b - a))) good = mid; else bad = mid;
  }
  return good;
}

double PlanningMap::clearance(Point2 p) const {
  std::call_once(labelled_, [this] { labelNearestObstacles(); });
  if (nearest_label_.empty()) return 1e9;
  const int cx = std::clamp(static_cast<int>(std::floor(p.x)), 0, raw_.width() - 1);
  const int cy = std::clamp(static_cast<int>(std::floor(p.y)), 0, raw_.height() - 1);
  double best = std::numeric_limits<double>::infinity();
  for (int y = std::max(0, cy - 1); y <= std::min(raw_.height() - 1, cy + 1); ++y) {
    for (int x = std::max(0, cx - 1); x <= std::min(raw_.width() - 1, cx + 1); ++x) {
      const int label = nearest_label_.at<int>(y, x);
      if (label < 0 || label >= static_cast<int>(obstacle_of_label_.size())) continue;
      const cv::Point cell = obstacle_of_label_[label];
      if (cell.x < 0) continue;
      const double dx = std::max({cell.x - p.x, 0.0, p.x - (cell.x + 1)});
      const double dy = std::max({cell.y - p.y, 0.0, p.y - (cell.y + 1)});
      best = std::min(best, std::sqrt(dx * dx + dy * dy));
    }
  }
  return best;
}

}  // namespace beft::planners

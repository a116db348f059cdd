#include "grid_map.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace beft::planners {

GridMap::GridMap(int width, int height) : width_(width), height_(height) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("grid size " + std::to_string(width) + " x " +
                                std::to_string(height) + " is not positive");
  }
  cells_.assign(static_cast<size_t>(width) * height, 0);
}

GridMap::GridMap(int width, int height, std::vector<uint8_t> cells) : GridMap(width, height) {
  if (cells.size() != cells_.size()) {
    throw std::invalid_argument("grid of " + std::to_string(width) + " x " + std::to_string(height) + " given " +
                                std::to_string(cells.size()) + " cells");
  }
  for (uint8_t& cell : cells) cell = cell != 0 ? 1 : 0;
  cells_ = std::move(cells);
}

void GridMap::setBlocked(int x, int y, bool blocked) {
  if (inside(x, y)) cells_[index(x, y)] = blocked ? 1 : 0;
}

void GridMap::fillRect(int x0, int y0, int x1, int y1, bool blocked) {
  for (int y = std::max(0, y0); y <= std::min(height_ - 1, y1); ++y) {
    for (int x = std::max(0, x0); x <= std::min(width_ - 1, x1); ++x) setBlocked(x, y, blocked);
  }
}

size_t GridMap::blockedCount() const {
  return static_cast<size_t>(std::count(cells_.begin(), cells_.end(), uint8_t{1}));
}

GridMap inflate(const GridMap& map, double radius_cells) {
  if (!(radius_cells >= 0) || !std::isfinite(radius_cells)) {
    throw std::invalid_argument("inflation radius must be a finite number >= 0");
  }
  if (radius_cells == 0 || map.width() == 0) return map;
  // Two unit squares whose centres differ by (dx, dy) cells come as close as
  // hypot(max(|dx|-1, 0), max(|dy|-1, 0)); the kernel holds the offsets
  // closer than the radius.
  const int reach = static_cast<int>(std::ceil(radius_cells)) + 1;
  cv::Mat kernel(2 * reach + 1, 2 * reach + 1, CV_8U, cv::Scalar(0));
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      const double gap = std::hypot(std::max(std::abs(dx) - 1, 0), std::max(std::abs(dy) - 1, 0));
      if (gap < radius_cells) kernel.at<uint8_t>(dy + reach, dx + reach) = 1;
    }
  }
  const cv::Mat source(map.height(), map.width(), CV_8U, const_cast<uint8_t*>(map.cells().data()));
  cv::Mat grown;
  cv::dilate(source, grown, kernel, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  // A fresh, continuous matrix: its rows are the grid's.
  return GridMap(map.width(), map.height(), std::vector<uint8_t>(grown.datastart, grown.dataend));
}

}  // namespace beft::planners

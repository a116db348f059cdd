#include "planners/grid_map.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
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

namespace {

// The offsets of blocked cells that block a cell, as a kernel: two unit
// squares whose centres differ by (dx, dy) cells come as close as
// hypot(max(|dx|-1, 0), max(|dy|-1, 0)); the kernel holds the offsets closer
// than the radius. reach: its half width.
cv::Mat inflationKernel(double radius_cells, int& reach) {
  reach = static_cast<int>(std::ceil(radius_cells)) + 1;
  cv::Mat kernel(2 * reach + 1, 2 * reach + 1, CV_8U, cv::Scalar(0));
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      const double gap = std::hypot(std::max(std::abs(dx) - 1, 0), std::max(std::abs(dy) - 1, 0));
      if (gap < radius_cells) kernel.at<uint8_t>(dy + reach, dx + reach) = 1;
    }
  }
  return kernel;
}

void checkRadius(double radius_cells) {
  if (!(radius_cells >= 0) || !std::isfinite(radius_cells)) {
    throw std::invalid_argument("inflation radius must be a finite number >= 0");
  }
}

}  // namespace

GridMap inflate(const GridMap& map, double radius_cells) {
  checkRadius(radius_cells);
  if (radius_cells == 0 || map.width() == 0) return map;
  int reach = 0;
  const cv::Mat kernel = inflationKernel(radius_cells, reach);
  const cv::Mat source(map.height(), map.width(), CV_8U, const_cast<uint8_t*>(map.cells().data()));
  cv::Mat grown;
  cv::dilate(source, grown, kernel, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  // A fresh, continuous matrix: its rows are the grid's.
  return GridMap(map.width(), map.height(), std::vector<uint8_t>(grown.datastart, grown.dataend));
}

bool differingRectangle(const uint8_t* a, const uint8_t* b, int width, int height, int& x0, int& y0, int& x1,
                        int& y1) {
  x0 = width, x1 = -1, y0 = height, y1 = -1;
  for (int y = 0; y < height; ++y) {  // whole rows compared first: most are the same
    const uint8_t* row_a = a + static_cast<size_t>(y) * width;
    const uint8_t* row_b = b + static_cast<size_t>(y) * width;
    if (std::memcmp(row_a, row_b, static_cast<size_t>(width)) == 0) continue;
    int first = 0, last = width - 1;
    while (row_a[first] == row_b[first]) ++first;
    while (row_a[last] == row_b[last]) --last;
    x0 = std::min(x0, first);
    x1 = std::max(x1, last);
    y0 = std::min(y0, y);
    y1 = y;
  }
  return x1 >= 0;
}

GridMap inflate(const GridMap& map, double radius_cells, const GridMap& earlier, const GridMap& earlier_inflated) {
  checkRadius(radius_cells);
  if (radius_cells == 0 || map.width() == 0) return map;
  const int width = map.width(), height = map.height();
  if (earlier.width() != width || earlier.height() != height) return inflate(map, radius_cells);
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  differingRectangle(map.cells().data(), earlier.cells().data(), width, height, x0, y0, x1, y1);
  return inflate(map, radius_cells, earlier_inflated, x0, y0, x1, y1);
}

GridMap inflate(const GridMap& map, double radius_cells, const GridMap& earlier_inflated, int x0, int y0, int x1,
                int y1) {
  checkRadius(radius_cells);
  if (radius_cells == 0 || map.width() == 0) return map;
  const int width = map.width(), height = map.height();
  if (earlier_inflated.width() != width || earlier_inflated.height() != height) return inflate(map, radius_cells);
  std::vector<uint8_t> cells = earlier_inflated.cells();
  if (x1 < x0 || y1 < y0) return GridMap(width, height, std::move(cells));
  // Cells within reach of a changed one may change; each of them depends on
  // the cells within reach of it.
  int reach = 0;
  const cv::Mat kernel = inflationKernel(radius_cells, reach);
  const cv::Rect grid(0, 0, width, height);
  const cv::Rect changed(x0 - reach, y0 - reach, x1 - x0 + 1 + 2 * reach, y1 - y0 + 1 + 2 * reach);
  const cv::Rect redone = changed & grid;
  if (redone.empty()) return GridMap(width, height, std::move(cells));
  const cv::Rect read = cv::Rect(changed.x - reach, changed.y - reach, changed.width + 2 * reach,
                                 changed.height + 2 * reach) & grid;
  const cv::Mat source(height, width, CV_8U, const_cast<uint8_t*>(map.cells().data()));
  // A copy of what is read: outside it, as outside the grid, counts as free.
  const cv::Mat around = source(read).clone();
  cv::Mat grown;
  cv::dilate(around, grown, kernel, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::Mat out(height, width, CV_8U, cells.data());
  grown(cv::Rect(redone.x - read.x, redone.y - read.y, redone.width, redone.height)).copyTo(out(redone));
  return GridMap(width, height, std::move(cells));
}

}  // namespace beft::planners

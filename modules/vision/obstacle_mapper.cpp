#include "obstacle_mapper.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "obstacle_map_codec.hpp"  // beft_obstacle_map

namespace beft::vision {

namespace {
constexpr uint8_t kUnknown = obstacle_map_t::CELL_UNKNOWN;
constexpr uint8_t kFree = obstacle_map_t::CELL_FREE;
constexpr uint8_t kOccupied = obstacle_map_t::CELL_OCCUPIED;
}  // namespace

ObstacleMapper::ObstacleMapper(double world_width, double world_height, const ObstacleMapConfig& config)
    : config_(config) {
  if (!(config.resolution > 0) || !std::isfinite(config.resolution))
    throw std::invalid_argument("obstacle map resolution must be > 0");
  if (!(world_width > 0) || !(world_height > 0) || !std::isfinite(world_width) || !std::isfinite(world_height))
    throw std::invalid_argument("world size must be > 0 to build an obstacle map");
  width_ = static_cast<int>(std::ceil(world_width / config.resolution - 1e-9));
  height_ = static_cast<int>(std::ceil(world_height / config.resolution - 1e-9));
  cells_.assign(static_cast<std::size_t>(width_) * height_, kUnknown);
  hit_in_frame_.assign(cells_.size(), 0);
}

bool ObstacleMapper::cellOf(double x, double y, int& column, int& row) const {
  if (!std::isfinite(x) || !std::isfinite(y)) return false;
  const double cx = std::floor(x / config_.resolution);
  const double cy = std::floor(y / config_.resolution);
  if (cx < 0 || cy < 0 || cx >= width_ || cy >= height_) return false;
  column = static_cast<int>(cx);
  row = static_cast<int>(cy);
  return true;
}

uint8_t ObstacleMapper::cell(int column, int row) const {
  if (column < 0 || row < 0 || column >= width_ || row >= height_) return kUnknown;
  return cells_[static_cast<std::size_t>(row) * width_ + column];
}

uint8_t ObstacleMapper::cellAt(double x, double y) const {
  int column = 0, row = 0;
  return cellOf(x, y, column, row) ? cell(column, row) : kUnknown;
}

int ObstacleMapper::countCells(uint8_t value) const {
  int count = 0;
  for (uint8_t c : cells_) count += (c == value);
  return count;
}

void ObstacleMapper::integrate(const Eigen::Vector3d& origin, const std::vector<DepthRay>& rays,
                               int free_space_stride) {
  ++frame_;
  if (free_space_stride < 1) free_space_stride = 1;
  // Obstacle returns first, so that free space of this frame never clears them.
  std::vector<std::size_t> obstacle_cells;
  for (const auto& ray : rays) {
    if (!(ray.t > 0) || !std::isfinite(ray.t)) continue;
    const Eigen::Vector3d hit = origin + ray.t * ray.direction;
    if (hit.z() <= config_.obstacle_min_height) continue;
    int column = 0, row = 0;
    if (!cellOf(hit.x(), hit.y(), column, row)) continue;
    const std::size_t index = static_cast<std::size_t>(row) * width_ + column;
    hit_in_frame_[index] = frame_;
    obstacle_cells.push_back(index);
  }
  for (std::size_t i = 0; i < rays.size(); i += static_cast<std::size_t>(free_space_stride)) {
    const auto& ray = rays[i];
    if (!(ray.t > 0) || !std::isfinite(ray.t)) continue;
    traverseFreeSpace(origin, ray.direction, ray.t);
  }
  for (std::size_t index : obstacle_cells) cells_[index] = kOccupied;
}

// Walks the cells under the ray's horizontal projection from the camera to
// just before the return (Amanatides-Woo grid traversal), with the ray's
// height where it enters and leaves each cell.
void ObstacleMapper::traverseFreeSpace(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                       double t_return) {
  const double range = t_return;  // ray parameter of the return
  int column = 0, row = 0;
  if (!cellOf(origin.x(), origin.y(), column, row)) return;
  const Eigen::Vector3d hit = origin + range * direction;
  int hit_column = -1, hit_row = -1;
  cellOf(hit.x(), hit.y(), hit_column, hit_row);

  const double r = config_.resolution;
  const double inf = std::numeric_limits<double>::infinity();
  const int step_x = direction.x() > 0 ? 1 : -1;
  const int step_y = direction.y() > 0 ? 1 : -1;
  const double next_x = (column + (step_x > 0 ? 1 : 0)) * r;
  const double next_y = (row + (step_y > 0 ? 1 : 0)) * r;
  double s_max_x = std::abs(direction.x()) > 1e-12 ? (next_x - origin.x()) / direction.x() : inf;
  double s_max_y = std::abs(direction.y()) > 1e-12 ? (next_y - origin.y()) / direction.y() : inf;
  const double s_delta_x = std::abs(direction.x()) > 1e-12 ? r / std::abs(direction.x()) : inf;
  const double s_delta_y = std::abs(direction.y()) > 1e-12 ? r / std::abs(direction.y()) : inf;

  double s_enter = 0;
  while (true) {
    if (column == hit_column && row == hit_row) {
      // The cell of a ground return: seen, but only part of it.
      if (hit.z() <= config_.obstacle_min_height) {
        auto& c = cells_[static_cast<std::size_t>(row) * width_ + column];
        if (c == kUnknown) c = kFree;
      }
      return;
    }
    const double s_exit = std::min({s_max_x, s_max_y, range});
    const std::size_t index = static_cast<std::size_t>(row) * width_ + column;
    auto& c = cells_[index];
    if (c == kUnknown) {
      c = kFree;
    } else if (c == kOccupied && hit_in_frame_[index] != frame_) {
      const double highest = std::max(origin.z() + s_enter * direction.z(), origin.z() + s_exit * direction.z());
      if (highest < config_.obstacle_min_height) c = kFree;
    }
    if (s_exit >= range) return;
    if (s_max_x < s_max_y) {
      column += step_x;
      s_enter = s_max_x;
      s_max_x += s_delta_x;
    } else {
      row += step_y;
      s_enter = s_max_y;
      s_max_y += s_delta_y;
    }
    if (column < 0 || row < 0 || column >= width_ || row >= height_) return;
  }
}

obstacle_map_t ObstacleMapper::toMessage(int64_t utime, int64_t tick) const {
  planners::ObstacleCells grid;  // origin (0, 0): the world's corner
  grid.width = width_;
  grid.height = height_;
  grid.resolution = config_.resolution;
  grid.cells = cells_;
  // RLE keeps a mostly uniform 60000-cell map at a few kB; raw bounds the worst case.
  const bool rle_smaller = planners::encodeRle(cells_).size() < cells_.size();
  return planners::makeObstacleMap(grid, rle_smaller ? obstacle_map_t::ENCODING_RLE : obstacle_map_t::ENCODING_RAW,
                                   utime, tick);
}

}  // namespace beft::vision

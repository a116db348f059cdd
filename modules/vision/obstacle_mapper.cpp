#include "obstacle_mapper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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

void ObstacleMapper::integrate(const Eigen::Vector3d& origin, const DepthImage& image) {
  if (image.width < 0 || image.height < 0 ||
      image.rays.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw std::invalid_argument("depth image of " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                " holds " + std::to_string(image.rays.size()) + " rays");
  ++frame_;
  auto hasReturn = [](const DepthRay& ray) { return ray.t > 0 && std::isfinite(ray.t); };

  // Obstacle returns first, so that no ray of this frame clears them.
  std::vector<std::size_t> obstacle_cells;
  for (const auto& ray : image.rays) {
    if (!hasReturn(ray)) continue;
    const Eigen::Vector3d hit = origin + ray.t * ray.direction;
    if (hit.z() <= config_.obstacle_min_height) continue;
    int column = 0, row = 0;
    if (!cellOf(hit.x(), hit.y(), column, row)) continue;
    const std::size_t index = static_cast<std::size_t>(row) * width_ + column;
    hit_in_frame_[index] = frame_;
    obstacle_cells.push_back(index);
  }
  // Per image column: seen cells along its farthest-reaching ray; then the
  // floor stretches of its floor returns, nearest first, each from where the
  // nearer one ended (the rays of a column share a horizontal direction when
  // the head is level, and the lowest ray over a cell is the one ending just
  // beyond it). Returns closer than a cell to the last one used add nothing.
  const double cell_diagonal = config_.resolution * M_SQRT2;
  std::vector<ColumnRay>& column_rays = column_rays_;
  for (int u = 0; u < image.width; ++u) {
    column_rays.clear();
    const DepthRay* farthest = nullptr;
    double farthest_reach = 0;
    for (int v = 0; v < image.height; ++v) {
      const DepthRay& ray = image.rays[static_cast<std::size_t>(v) * image.width + u];
      if (!hasReturn(ray)) continue;
      const double horizontal = std::sqrt(ray.direction.x() * ray.direction.x() + ray.direction.y() * ray.direction.y());
      const double reach = ray.t * horizontal;
      if (reach > farthest_reach) {
        farthest_reach = reach;
        farthest = &ray;
      }
      if (origin.z() + ray.t * ray.direction.z() <= config_.obstacle_min_height)
        column_rays.push_back({reach, horizontal, &ray});
    }
    if (farthest != nullptr) markSeen(origin, *farthest);
    std::sort(column_rays.begin(), column_rays.end(),
              [](const ColumnRay& a, const ColumnRay& b) { return a.reach < b.reach; });
    double covered = -1;  // horizontal distance up to which a nearer ray ran low
    for (const ColumnRay& c : column_rays) {
      if (covered >= 0 && c.reach < covered + config_.resolution) continue;
      const double t_from = covered > 0 && c.horizontal > 0 ? std::max(0.0, (covered - cell_diagonal) / c.horizontal) : 0.0;
      clearBelowThreshold(origin, *c.ray, t_from);
      covered = c.reach;
    }
  }
  for (std::size_t index : obstacle_cells) set(index, kOccupied);
}

template <typename Visit>
void ObstacleMapper::traverse(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_begin, double t_end,
                              Visit&& visit) const {
  const Eigen::Vector3d start = o + t_begin * d;
  int column = 0, row = 0;
  if (!cellOf(start.x(), start.y(), column, row)) return;
  const Eigen::Vector3d end = o + t_end * d;
  int end_column = -1, end_row = -1;
  cellOf(end.x(), end.y(), end_column, end_row);

  const double r = config_.resolution;
  const double inf = std::numeric_limits<double>::infinity();
  const int step_x = d.x() > 0 ? 1 : -1;
  const int step_y = d.y() > 0 ? 1 : -1;
  const bool moves_x = std::abs(d.x()) > 1e-12, moves_y = std::abs(d.y()) > 1e-12;
  double t_next_x = moves_x ? ((column + (step_x > 0 ? 1 : 0)) * r - o.x()) / d.x() : inf;
  double t_next_y = moves_y ? ((row + (step_y > 0 ? 1 : 0)) * r - o.y()) / d.y() : inf;
  const double t_delta_x = moves_x ? r / std::abs(d.x()) : inf;
  const double t_delta_y = moves_y ? r / std::abs(d.y()) : inf;

  double t_enter = t_begin;
  while (!(column == end_column && row == end_row)) {
    const double t_exit = std::min({t_next_x, t_next_y, t_end});
    visit(static_cast<std::size_t>(row) * width_ + column, t_enter, t_exit);
    if (t_exit >= t_end) return;
    if (t_next_x < t_next_y) {
      column += step_x;
      t_enter = t_next_x;
      t_next_x += t_delta_x;
    } else {
      row += step_y;
      t_enter = t_next_y;
      t_next_y += t_delta_y;
    }
    if (column < 0 || row < 0 || column >= width_ || row >= height_) return;
  }
}

// UNKNOWN -> FREE along the ray up to its return; the cell of a floor return
// is seen too.
void ObstacleMapper::markSeen(const Eigen::Vector3d& origin, const DepthRay& ray) {
  traverse(origin, ray.direction, 0.0, ray.t, [&](std::size_t index, double, double) {
    if (cells_[index] == kUnknown) set(index, kFree);
  });
  const Eigen::Vector3d hit = origin + ray.t * ray.direction;
  int column = 0, row = 0;
  if (hit.z() <= config_.obstacle_min_height && cellOf(hit.x(), hit.y(), column, row)) {
    const std::size_t index = static_cast<std::size_t>(row) * width_ + column;
    if (cells_[index] == kUnknown) set(index, kFree);
  }
}

// Where the ray runs below the obstacle height it proves the floor empty:
// clears obstacles of earlier frames there (and marks the cells seen).
void ObstacleMapper::clearBelowThreshold(const Eigen::Vector3d& origin, const DepthRay& ray, double t_from) {
  const double threshold = config_.obstacle_min_height;
  double t_below = t_from;  // from where on the ray stays below the threshold
  if (origin.z() >= threshold) {
    if (!(ray.direction.z() < 0)) return;
    t_below = std::max(t_from, (threshold - origin.z()) / ray.direction.z());
    if (t_below >= ray.t) return;
  }
  // The first cell is entered part way: the ray's height where it truly
  // entered it is unknown here, so it only counts as seen.
  bool first_cell = true;
  traverse(origin, ray.direction, t_below, ray.t, [&](std::size_t index, double t_enter, double t_exit) {
    const uint8_t c = cells_[index];
    if (c == kUnknown) {
      set(index, kFree);
    } else if (c == kOccupied && !first_cell && hit_in_frame_[index] != frame_) {
      const double highest = origin.z() + std::max(t_enter * ray.direction.z(), t_exit * ray.direction.z());
      if (highest < threshold) set(index, kFree);
    }
    first_cell = false;
  });
}

void ObstacleMapper::restoreCells(const std::vector<uint8_t>& cells) {
  if (cells.size() != cells_.size())
    throw std::invalid_argument("cannot restore " + std::to_string(cells.size()) + " cells into a map of " +
                                std::to_string(cells_.size()));
  for (uint8_t c : cells)
    if (c != kUnknown && c != kFree && c != kOccupied)
      throw std::invalid_argument("cannot restore a cell of value " + std::to_string(c));
  cells_ = cells;
  ++version_;
}

obstacle_map_t ObstacleMapper::toMessage(int64_t utime, int64_t tick) const {
  planners::ObstacleCells grid;  // origin (0, 0): the world's corner
  grid.width = width_;
  grid.height = height_;
  grid.resolution = config_.resolution;
  grid.cells = cells_;
  // RLE keeps a mostly uniform 60000-cell map at a few kB; raw bounds the worst case.
  obstacle_map_t map = planners::makeObstacleMap(grid, obstacle_map_t::ENCODING_RLE, utime, tick);
  if (map.data.size() >= cells_.size()) map = planners::makeObstacleMap(grid, obstacle_map_t::ENCODING_RAW, utime, tick);
  return map;
}

}  // namespace beft::vision

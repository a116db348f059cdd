#include "experts/vision/obstacle_mapper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "experts/vision/depth_rays.hpp"
#include "lib/wire/obstacle_map_codec.hpp"  // beft_obstacle_map

namespace beft::vision {

namespace {
constexpr uint8_t kUnknown = obstacle_map_t::CELL_UNKNOWN;
constexpr uint8_t kFree = obstacle_map_t::CELL_FREE;
constexpr uint8_t kOccupied = obstacle_map_t::CELL_OCCUPIED;

// Length of a ray direction's horizontal part (one formula wherever it is needed, so it is the same number).
inline double horizontalLength(const DepthRay& ray) {
  return std::sqrt(ray.direction.x() * ray.direction.x() + ray.direction.y() * ray.direction.y());
}
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
  hit_this_frame_.assign(cells_.size(), 0);
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
  integrateRays(origin, image.width, image.height, image.level,
                [&image](int u, int v) -> const DepthRay& { return image.rays[static_cast<std::size_t>(v) * image.width + u]; });
}

void ObstacleMapper::integrate(const DepthFrameRays& rays) {
  int row_of_start = -1;
  Eigen::Vector3d row_start = Eigen::Vector3d::Zero();
  DepthRay ray;
  const uint8_t* const depth_bytes = rays.depthBytes();  // locals: see integrateRays
  const Eigen::Vector3d* const column_steps = &rays.columnStep(0);
  const int width = rays.width();
  integrateRays(rays.origin(), width, rays.height(), rays.level(), [&](int u, int v) -> const DepthRay& {
    if (v != row_of_start) {
      row_start = rays.rowStart(v);
      row_of_start = v;
    }
    ray.direction = row_start + column_steps[u];
    ray.t = DepthFrameRays::depthOfPixel(depth_bytes, static_cast<std::size_t>(v) * width + u);
    return ray;
  });
}

template <typename RayAt>
void ObstacleMapper::integrateRays(const Eigen::Vector3d& origin, int width, int height, bool level, RayAt&& ray_at) {
  auto hasReturn = [](const DepthRay& ray) { return ray.t > 0 && std::isfinite(ray.t); };

  // One pass over the rays, bottom row first: obstacle returns (marked
  // last, so that no ray of this frame clears them), and per image column its
  // farthest-reaching ray and its floor returns (at most obstacle_min_height
  // high), nearly in order of reach.
  std::vector<std::size_t>& obstacle_cells = obstacle_cells_;
  obstacle_cells.clear();
  columns_.resize(static_cast<std::size_t>(width));
  for (auto& column : columns_) {
    column.farthest_v = -1;
    column.farthest_reach = 0;
    column.floor_rays.clear();
  }
  // Locals, not members: the byte stores below (hit_this_frame_) may alias
  // anything, and members would be reloaded on every pixel.
  const double ox = origin.x(), oy = origin.y(), oz = origin.z();
  const double floor_height = config_.obstacle_min_height;
  uint8_t* const hit_this_frame = hit_this_frame_.data();
  ColumnScan* const columns = columns_.data();
  for (int v = height - 1; v >= 0; --v) {
    for (int u = 0; u < width; ++u) {
      const DepthRay& ray = ray_at(u, v);
      if (!hasReturn(ray)) continue;
      const double hit_x = ox + ray.t * ray.direction.x();
      const double hit_y = oy + ray.t * ray.direction.y();
      const double hit_z = oz + ray.t * ray.direction.z();
      const double reach = ray.t * horizontalLength(ray);
      ColumnScan& column = columns[u];
      if (reach > column.farthest_reach) {
        column.farthest_reach = reach;
        column.farthest_v = v;
      }
      if (hit_z <= floor_height) {
        // Written in place: a braced temporary is two narrow stores read back as one
        // wide load, which stalls store-to-load forwarding on every floor pixel.
        ColumnRay& floor = column.floor_rays.emplace_back();
        floor.reach = reach;
        floor.v = v;
        continue;
      }
      int cell_column = 0, cell_row = 0;
      if (!cellOf(hit_x, hit_y, cell_column, cell_row)) continue;
      const std::size_t index = static_cast<std::size_t>(cell_row) * width_ + cell_column;
      hit_this_frame[index] = 1;
      obstacle_cells.push_back(index);
    }
  }
  for (int u = 0; u < width; ++u) {
    ColumnScan& column = columns_[u];
    if (column.farthest_v < 0) continue;
    // Insertion sort: the bottom rows reach nearest, so this is nearly in order already.
    auto& rays = column.floor_rays;
    for (std::size_t i = 1; i < rays.size(); ++i)
      for (std::size_t k = i; k > 0 && rays[k].reach < rays[k - 1].reach; --k) std::swap(rays[k], rays[k - 1]);
    const DepthRay farthest = ray_at(u, column.farthest_v);  // a copy: ray_at may reuse its result
    if (level)
      walkLevelColumn(origin, u, farthest, column.farthest_reach, column.floor_rays, ray_at);
    else
      traceColumnRays(origin, u, farthest, column.floor_rays, ray_at);
  }
  for (std::size_t index : obstacle_cells) set(index, kOccupied);
  for (std::size_t index : obstacle_cells) hit_this_frame_[index] = 0;
}

template <typename Visit>
void ObstacleMapper::traverse(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_begin, double t_end,
                              Visit&& visit) const {
  const Eigen::Vector3d start = o + t_begin * d;
  int column = 0, row = 0;
  if (!cellOf(start.x(), start.y(), column, row)) return;
  const Eigen::Vector3d end = o + t_end * d;
  int end_column = -1, end_row = -1;
  const bool end_inside = cellOf(end.x(), end.y(), end_column, end_row);

  const double r = config_.resolution;
  const double inf = std::numeric_limits<double>::infinity();
  const int step_x = d.x() > 0 ? 1 : -1;
  const int step_y = d.y() > 0 ? 1 : -1;
  const bool moves_x = std::abs(d.x()) > 1e-12, moves_y = std::abs(d.y()) > 1e-12;
  double t_next_x = moves_x ? ((column + (step_x > 0 ? 1 : 0)) * r - o.x()) / d.x() : inf;
  double t_next_y = moves_y ? ((row + (step_y > 0 ? 1 : 0)) * r - o.y()) / d.y() : inf;
  const double t_delta_x = moves_x ? r / std::abs(d.x()) : inf;
  const double t_delta_y = moves_y ? r / std::abs(d.y()) : inf;

  // The walk in cell indices: a step in x or y is a fixed offset, and the
  // steps left before the grid's edge are counted down (the hot loop of the
  // map: every column of every frame walks a ray's length of cells).
  const std::ptrdiff_t row_step = static_cast<std::ptrdiff_t>(step_y) * width_;
  int steps_x_left = step_x > 0 ? width_ - 1 - column : column;
  int steps_y_left = step_y > 0 ? height_ - 1 - row : row;
  std::size_t index = static_cast<std::size_t>(row) * width_ + column;
  const std::size_t end_index =
      end_inside ? static_cast<std::size_t>(end_row) * width_ + end_column : std::numeric_limits<std::size_t>::max();
  double t_enter = t_begin;
  while (index != end_index) {
    const double t_exit = std::min({t_next_x, t_next_y, t_end});
    visit(index, t_enter, t_exit);
    if (t_exit >= t_end) return;
    if (t_next_x < t_next_y) {
      if (--steps_x_left < 0) return;
      index += step_x;
      t_enter = t_next_x;
      t_next_x += t_delta_x;
    } else {
      if (--steps_y_left < 0) return;
      index += row_step;
      t_enter = t_next_y;
      t_next_y += t_delta_y;
    }
  }
}

// A level camera: every ray of the column runs in one vertical plane, so a
// single walk along the column's horizontal direction marks the seen cells,
// and each cell is checked against the lowest floor ray over it: the one
// whose return is nearest beyond the cell (it descends, so it is highest
// where it enters the cell).
template <typename RayAt>
void ObstacleMapper::walkLevelColumn(const Eigen::Vector3d& origin, int u, const DepthRay& farthest, double reach,
                                     const std::vector<ColumnRay>& floor_rays, RayAt& ray_at) {
  const double horizontal = horizontalLength(farthest);
  if (!(horizontal > 0)) return;
  const Eigen::Vector3d along(farthest.direction.x() / horizontal, farthest.direction.y() / horizontal, 0.0);
  const double threshold = config_.obstacle_min_height;
  std::size_t lowest = 0;  // first floor ray reaching beyond the current cell
  traverse(origin, along, 0.0, reach, [&](std::size_t index, double s_enter, double s_exit) {
    const uint8_t c = cells_[index];
    if (c == kUnknown) {
      set(index, kFree);
    } else if (c == kOccupied && !hit_this_frame_[index]) {
      while (lowest < floor_rays.size() && floor_rays[lowest].reach <= s_exit) ++lowest;
      if (lowest < floor_rays.size()) {
        const DepthRay& r = ray_at(u, floor_rays[lowest].v);
        const double height = origin.z() + s_enter * r.direction.z() / horizontalLength(r);
        if (height < threshold) set(index, kFree);
      }
    }
  });
  markReturnCellSeen(origin, farthest);
}

// A tilted camera: the rays of a column fan out horizontally. Seen cells
// along the farthest ray; then each floor ray's stretch below the obstacle
// height, nearest first, from where the nearer one ended. Returns closer than
// a cell to the last one used add nothing.
template <typename RayAt>
void ObstacleMapper::traceColumnRays(const Eigen::Vector3d& origin, int u, const DepthRay& farthest,
                                     const std::vector<ColumnRay>& floor_rays, RayAt& ray_at) {
  markSeen(origin, farthest);
  const double cell_diagonal = config_.resolution * M_SQRT2;
  double covered = -1;  // horizontal distance up to which a nearer ray ran low
  for (const ColumnRay& c : floor_rays) {
    if (covered >= 0 && c.reach < covered + config_.resolution) continue;
    const DepthRay ray = ray_at(u, c.v);
    const double horizontal = horizontalLength(ray);
    const double t_from = covered > 0 && horizontal > 0 ? std::max(0.0, (covered - cell_diagonal) / horizontal) : 0.0;
    clearBelowThreshold(origin, ray, t_from);
    covered = c.reach;
  }
}

// UNKNOWN -> FREE along the ray up to its return; the cell of a floor return
// is seen too.
void ObstacleMapper::markSeen(const Eigen::Vector3d& origin, const DepthRay& ray) {
  traverse(origin, ray.direction, 0.0, ray.t, [&](std::size_t index, double, double) {
    if (cells_[index] == kUnknown) set(index, kFree);
  });
  markReturnCellSeen(origin, ray);
}

void ObstacleMapper::markReturnCellSeen(const Eigen::Vector3d& origin, const DepthRay& ray) {
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
    } else if (c == kOccupied && !first_cell && !hit_this_frame_[index]) {
      const double highest = origin.z() + std::max(t_enter * ray.direction.z(), t_exit * ray.direction.z());
      if (highest < threshold) set(index, kFree);
    }
    first_cell = false;
  });
}

void ObstacleMapper::markContact(double x, double y, double heading_deg, double width, double radius) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(heading_deg) || !std::isfinite(width) ||
      !std::isfinite(radius))
    return;
  const double r = std::max(radius, 0.5 * config_.resolution);
  const double half = std::max(0.0, width) / 2;
  // The segment runs across the heading.
  const double ux = -std::sin(heading_deg * M_PI / 180.0), uy = std::cos(heading_deg * M_PI / 180.0);
  const double reach = half + r;
  const auto cellRange = [&](double low, double high, int cells) {
    const double first = std::max(0.0, std::floor(low / config_.resolution));
    const double last = std::min(cells - 1.0, std::floor(high / config_.resolution));
    return std::make_pair(static_cast<int>(first), static_cast<int>(last));
  };
  const auto [c0, c1] = cellRange(x - reach, x + reach, width_);
  const auto [r0, r1] = cellRange(y - reach, y + reach, height_);
  for (int row = r0; row <= r1; ++row) {
    for (int column = c0; column <= c1; ++column) {
      const double dx = (column + 0.5) * config_.resolution - x, dy = (row + 0.5) * config_.resolution - y;
      const double along = std::clamp(dx * ux + dy * uy, -half, half);
      if (std::hypot(dx - along * ux, dy - along * uy) > r) continue;
      const std::size_t index = static_cast<std::size_t>(row) * width_ + column;
      felt_.insert(index);
      set(index, kOccupied);
    }
  }
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
  changed_ = {};
}

obstacle_map_changes_t ObstacleMapper::changesMessage(int64_t keyframe_tick, int64_t utime, int64_t tick) const {
  return planners::makeMapChanges(cells_, width_, height_, changed_, keyframe_tick, utime, tick);
}

obstacle_map_t ObstacleMapper::toMessage(int64_t utime, int64_t tick) const {
  planners::ObstacleCells grid;  // origin (0, 0): the world's corner
  grid.width = width_;
  grid.height = height_;
  grid.resolution = config_.resolution;
  grid.cells = cells_;
  // RLE keeps a mostly uniform 60000-cell map at a few kB; raw bounds the worst case.
  obstacle_map_t map = planners::makeObstacleMap(grid, obstacle_map_t::ENCODING_RLE_ZSTD, utime, tick);
  if (map.data.size() >= cells_.size()) map = planners::makeObstacleMap(grid, obstacle_map_t::ENCODING_RAW, utime, tick);
  return map;
}

}  // namespace beft::vision

#include "experts/exploration/known_map.hpp"

#include "experts/exploration/target_cells.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <beft/obstacle_map_t.hpp>


namespace beft::exploration {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

KnownMap::KnownMap(planners::ObstacleCells cells, double radius) : cells_(std::move(cells)) {
  radius_cells_ = std::max(0.0, radius / cells_.resolution);
  // The world's border is a wall: the robot's disc stays inside.
  border_ = static_cast<int>(std::ceil(radius_cells_ - 0.5));
  // The offsets planners::inflate's kernel holds (squares closer than the radius).
  if (radius_cells_ > 0) {
    const int reach = static_cast<int>(std::ceil(radius_cells_)) + 1;
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx)
        if (std::hypot(std::max(std::abs(dx) - 1, 0), std::max(std::abs(dy) - 1, 0)) < radius_cells_)
          reach_offsets_.emplace_back(dx, dy);
  } else {
    reach_offsets_.emplace_back(0, 0);
  }
}

KnownMap::KnownMap(planners::ObstacleCells cells, double radius, KnownMap&& earlier)
    : KnownMap(std::move(cells), radius) {
  if (earlier.radius_cells_ != radius_cells_) return;
  if (earlier.standing_) {
    earlier_cells_ = std::move(earlier.cells_);
    earlier_standing_ = std::move(earlier.standing_);
  } else if (earlier.earlier_standing_) {
    earlier_cells_ = std::move(earlier.earlier_cells_);
    earlier_standing_ = std::move(earlier.earlier_standing_);
  }
}

const planners::GridMap& KnownMap::standing() const {
  if (standing_) return *standing_;
  std::vector<uint8_t> flags(cells_.cells.size());
  std::transform(cells_.cells.begin(), cells_.cells.end(), flags.begin(),
                 [](uint8_t cell) { return cell == obstacle_map_t::CELL_OCCUPIED ? 1 : 0; });
  const planners::GridMap occupied(cells_.width, cells_.height, std::move(flags));
  // From the earlier map's grid when there is one of the same size: its
  // border is filled, as this one's is below, and every cell within reach of
  // a changed one is inflated again.
  planners::GridMap standing = inflatedAgain(occupied);
  if (border_ > 0) {
    standing.fillRect(0, 0, cells_.width - 1, border_ - 1);
    standing.fillRect(0, cells_.height - border_, cells_.width - 1, cells_.height - 1);
    standing.fillRect(0, 0, border_ - 1, cells_.height - 1);
    standing.fillRect(cells_.width - border_, 0, cells_.width - 1, cells_.height - 1);
  }
  standing_ = std::move(standing);
  return *standing_;
}

planners::GridMap KnownMap::inflatedAgain(const planners::GridMap& occupied) const {
  const bool same_size = earlier_cells_ && earlier_standing_ && earlier_cells_->width == cells_.width &&
                         earlier_cells_->height == cells_.height;
  if (!same_size) return planners::inflate(occupied, radius_cells_);
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // the cells that changed
  planners::differingRectangle(cells_.cells.data(), earlier_cells_->cells.data(), cells_.width, cells_.height, x0, y0,
                               x1, y1);
  planners::GridMap standing = planners::inflate(occupied, radius_cells_, *earlier_standing_, x0, y0, x1, y1);
  earlier_cells_.reset();
  earlier_standing_.reset();
  return standing;
}

bool KnownMap::standable(int x, int y) const {
  if (!inside(x, y)) return false;
  if (standing_) return !standing_->blocked(x, y);
  if (x < border_ || y < border_ || x >= cells_.width - border_ || y >= cells_.height - border_) return false;
  for (const auto& [dx, dy] : reach_offsets_) {
    const int ox = x + dx, oy = y + dy;
    if (inside(ox, oy) && cells_.at(ox, oy) == obstacle_map_t::CELL_OCCUPIED) return false;
  }
  return true;
}

uint8_t KnownMap::at(int x, int y) const {
  return inside(x, y) ? cells_.at(x, y) : static_cast<uint8_t>(obstacle_map_t::CELL_OCCUPIED);
}

bool KnownMap::cellOf(double wx, double wy, Cell& cell) const {
  const double fx = (wx - cells_.origin_x) / cells_.resolution;
  const double fy = (wy - cells_.origin_y) / cells_.resolution;
  if (!std::isfinite(fx) || !std::isfinite(fy)) return false;
  cell = {static_cast<int>(std::floor(fx)), static_cast<int>(std::floor(fy))};
  return inside(cell.x, cell.y);
}

SightLine KnownMap::sight(double ax, double ay, double bx, double by, double ignore_near_b,
                          const TargetCells* own) const {
  // Every cell the segment crosses, in order (Amanatides & Woo's grid walk).
  SightLine line;
  const double length = std::hypot(bx - ax, by - ay);
  const double fx = (ax - cells_.origin_x) / cells_.resolution, fy = (ay - cells_.origin_y) / cells_.resolution;
  const double dx = (bx - ax) / cells_.resolution, dy = (by - ay) / cells_.resolution;
  if (!std::isfinite(fx + fy + dx + dy)) return line;
  int x = static_cast<int>(std::floor(fx)), y = static_cast<int>(std::floor(fy));
  const int step_x = dx > 0 ? 1 : -1, step_y = dy > 0 ? 1 : -1;
  const double t_delta_x = dx != 0 ? std::abs(1.0 / dx) : kInfinity;
  const double t_delta_y = dy != 0 ? std::abs(1.0 / dy) : kInfinity;
  double t_max_x = dx != 0 ? ((dx > 0 ? std::floor(fx) + 1 - fx : fx - std::floor(fx)) * t_delta_x) : kInfinity;
  double t_max_y = dy != 0 ? ((dy > 0 ? std::floor(fy) + 1 - fy : fy - std::floor(fy)) * t_delta_y) : kInfinity;
  double t_enter = 0;  // where the walk entered the current cell, as a fraction of the segment
  while (t_enter <= 1.0) {
    if ((1.0 - t_enter) * length < ignore_near_b) break;  // the target's own footprint from here on
    if (!inside(x, y)) return line;                       // leaves the map: no sight
    const uint8_t value = cells_.at(x, y);
    if (value == obstacle_map_t::CELL_OCCUPIED) {
      if (own != nullptr && own->contains(x, y)) break;  // the target's near side
      return line;
    }
    const double t_exit = std::min({t_max_x, t_max_y, 1.0});
    if (value == obstacle_map_t::CELL_UNKNOWN) line.unknown_m += (t_exit - t_enter) * length;
    if (t_max_x < t_max_y) {
      t_enter = t_max_x;
      t_max_x += t_delta_x;
      x += step_x;
    } else {
      t_enter = t_max_y;
      t_max_y += t_delta_y;
      y += step_y;
    }
    if (t_exit >= 1.0) break;
  }
  line.clear = true;
  return line;
}

TravelField::TravelField(const KnownMap& map, double robot_x, double robot_y, double escape_radius)
    : width_(map.width()), height_(map.height()), resolution_(map.resolution()) {
  Cell start;
  if (!map.cellOf(robot_x, robot_y, start)) return;
  planners::GridMap grid = map.standing();
  // Let a robot that stands (or believes it stands) too close to an obstacle
  // drive away from it: free the inflated, not occupied, cells around it.
  const int reach = static_cast<int>(std::ceil(escape_radius / resolution_));
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx) {
      const int x = start.x + dx, y = start.y + dy;
      if (std::hypot(dx, dy) * resolution_ <= escape_radius && map.inside(x, y) &&
          map.at(x, y) != obstacle_map_t::CELL_OCCUPIED)
        grid.setBlocked(x, y, false);
    }
  // A window of 20 m around the robot at first: most questions are about nearer places.
  const int first_reach = static_cast<int>(std::ceil(20.0 / resolution_));
  wavefront_.emplace(std::move(grid), planners::GridCell{start.x, start.y}, first_reach);
}

double TravelField::at(int x, int y) const {
  if (!wavefront_ || x < 0 || y < 0 || x >= width_ || y >= height_) return kInfinity;
  wavefront_->growUntilFinal({x, y});
  return wavefront_->value(x, y) * resolution_;
}

bool TravelField::reachable(int x, int y) const { return std::isfinite(at(x, y)); }

double TravelField::within(int x, int y, double limit_m) const {
  if (!(limit_m < kInfinity)) return at(x, y);
  if (!wavefront_ || x < 0 || y < 0 || x >= width_ || y >= height_ || !(limit_m >= 0)) return kInfinity;
  const double limit_cells = limit_m / resolution_;
  // Every bucket that can hold a distance up to the limit.
  wavefront_->growThroughBucket(static_cast<int64_t>(std::min(std::floor(limit_cells), 9e18)));
  if (!wavefront_->isFinal(x, y)) return kInfinity;
  const double travel = wavefront_->value(x, y) * resolution_;
  return travel <= limit_m ? travel : kInfinity;
}

}  // namespace beft::exploration

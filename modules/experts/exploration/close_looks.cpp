#include "experts/exploration/close_looks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <beft/obstacle_map_t.hpp>

#include "experts/exploration/cheapest_first.hpp"

namespace beft::exploration {
namespace {

double angleBetweenDeg(double a, double b) {
  double difference = std::fmod(a - b + 180.0, 360.0);
  if (difference < 0) difference += 360.0;
  return std::abs(difference - 180.0);
}

// The near end of a sight line to a cell's centre: a person lying there
// fills the map cells at its centre, which must not hide it from itself.
constexpr double kOwnFootprintM = 0.3;

}  // namespace

void CloseLookCoverage::fit(const KnownMap& map) {
  const double map_width_m = map.width() * map.resolution(), map_height_m = map.height() * map.resolution();
  const double origin_x = map.centreX(0) - 0.5 * map.resolution(), origin_y = map.centreY(0) - 0.5 * map.resolution();
  if (map_width_m == map_width_m_ && map_height_m == map_height_m_ && origin_x == origin_x_ && origin_y == origin_y_)
    return;
  map_width_m_ = map_width_m;
  map_height_m_ = map_height_m;
  origin_x_ = origin_x;
  origin_y_ = origin_y;
  width_ = std::max(1, static_cast<int>(std::ceil(map_width_m / parameters_.cell_m)));
  height_ = std::max(1, static_cast<int>(std::ceil(map_height_m / parameters_.cell_m)));
  state_.assign(static_cast<size_t>(width_) * height_, kNotLooked);
  looked_at_ = 0;
  last_camera_.reset();
}

bool CloseLookCoverage::cellOf(double wx, double wy, Cell& cell) const {
  const double fx = (wx - origin_x_) / parameters_.cell_m, fy = (wy - origin_y_) / parameters_.cell_m;
  if (!std::isfinite(fx) || !std::isfinite(fy) || fx < 0 || fy < 0 || fx >= width_ || fy >= height_) return false;
  cell = {static_cast<int>(fx), static_cast<int>(fy)};
  return true;
}

bool CloseLookCoverage::ground(const KnownMap& map, int x, int y) const {
  Cell on_map;
  return map.cellOf(centreX(x), centreY(y), on_map) && map.at(on_map.x, on_map.y) == obstacle_map_t::CELL_FREE;
}

void CloseLookCoverage::look(const KnownMap& map, double x, double y, double gaze_deg) {
  if (!parameters_.enabled || !std::isfinite(x + y + gaze_deg)) return;
  fit(map);
  if (last_camera_ && std::hypot(x - last_camera_->x, y - last_camera_->y) < parameters_.pose_step_m &&
      angleBetweenDeg(gaze_deg, last_gaze_deg_) < parameters_.gaze_step_deg)
    return;
  last_camera_ = Point{x, y};
  last_gaze_deg_ = gaze_deg;
  const double range = parameters_.range_m, half_fov = 0.5 * parameters_.fov_deg;
  const int reach = static_cast<int>(std::ceil(range / parameters_.cell_m)) + 1;
  // The camera's cell, clamped: one far off the map looks at none of it.
  const Cell camera{static_cast<int>(std::clamp(std::floor((x - origin_x_) / parameters_.cell_m), -2.0 * reach,
                                                width_ + 2.0 * reach)),
                    static_cast<int>(std::clamp(std::floor((y - origin_y_) / parameters_.cell_m), -2.0 * reach,
                                                height_ + 2.0 * reach))};
  for (int cy = std::max(0, camera.y - reach); cy <= std::min(height_ - 1, camera.y + reach); ++cy)
    for (int cx = std::max(0, camera.x - reach); cx <= std::min(width_ - 1, camera.x + reach); ++cx) {
      uint8_t& state = state_[index(cx, cy)];
      if (state == kLooked) continue;
      const double px = centreX(cx), py = centreY(cy);
      const double distance = std::hypot(px - x, py - y);
      if (distance > range || angleBetweenDeg(bearingDeg(x, y, px, py), gaze_deg) > half_fov) continue;
      if (!ground(map, cx, cy) || !map.sight(x, y, px, py, kOwnFootprintM).clear) continue;
      state = kLooked;
      ++looked_at_;
    }
}

void CloseLookCoverage::visited(const KnownMap& map, Point goal) {
  if (!parameters_.enabled) return;
  fit(map);
  const int reach = static_cast<int>(std::ceil(parameters_.range_m / parameters_.cell_m)) + 1;
  Cell centre;
  if (!cellOf(goal.x, goal.y, centre)) return;
  for (int cy = std::max(0, centre.y - reach); cy <= std::min(height_ - 1, centre.y + reach); ++cy)
    for (int cx = std::max(0, centre.x - reach); cx <= std::min(width_ - 1, centre.x + reach); ++cx) {
      uint8_t& state = state_[index(cx, cy)];
      if (state != kNotLooked) continue;
      const double px = centreX(cx), py = centreY(cy);
      const double distance = std::hypot(px - goal.x, py - goal.y);
      if (distance <= parameters_.visited_radius_m) {
        state = kGivenUp;
        continue;
      }
      // Within hidden_near_goal_m of the goal (the default, 100 m, covers the
      // whole range): whatever hides it stands that near, so it stays open
      // without walking the line at all.
      const double ignored_near_cell = distance - parameters_.hidden_near_goal_m;
      if (distance > parameters_.range_m || ignored_near_cell <= kOwnFootprintM) continue;
      // Given up if hidden, but not by what stands near the goal (the
      // line's first hidden_near_goal_m, the rest of it ignored).
      if (map.sight(goal.x, goal.y, px, py, ignored_near_cell).clear &&
          !map.sight(goal.x, goal.y, px, py, kOwnFootprintM).clear)
        state = kGivenUp;
    }
}

bool CloseLookCoverage::open(double x, double y) const {
  if (!parameters_.enabled) return false;
  Cell cell;
  return state_.empty() || !cellOf(x, y, cell) || state_[index(cell.x, cell.y)] == kNotLooked;
}

int CloseLookCoverage::openGroundNear(const KnownMap& map, double x, double y, double radius) const {
  if (!parameters_.enabled || state_.empty()) return 0;
  Cell centre;
  if (!cellOf(x, y, centre)) return 0;
  const int reach = static_cast<int>(std::ceil(radius / parameters_.cell_m)) + 1;
  int open_ground = 0;
  for (int cy = std::max(0, centre.y - reach); cy <= std::min(height_ - 1, centre.y + reach); ++cy)
    for (int cx = std::max(0, centre.x - reach); cx <= std::min(width_ - 1, centre.x + reach); ++cx)
      if (state_[index(cx, cy)] == kNotLooked && std::hypot(centreX(cx) - x, centreY(cy) - y) <= radius &&
          ground(map, cx, cy))
        ++open_ground;
  return open_ground;
}

std::vector<std::vector<Cell>> CloseLookCoverage::openPatches(const KnownMap& map) const {
  std::vector<uint8_t> mask(state_.size(), 0);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) mask[index(x, y)] = state_[index(x, y)] == kNotLooked && ground(map, x, y);
  std::vector<std::vector<Cell>> patches;
  std::vector<Cell> patch, stack;
  for (int y0 = 0; y0 < height_; ++y0)
    for (int x0 = 0; x0 < width_; ++x0) {
      if (!mask[index(x0, y0)]) continue;
      patch.clear();
      stack.assign(1, {x0, y0});
      mask[index(x0, y0)] = 0;
      while (!stack.empty()) {
        const Cell c = stack.back();
        stack.pop_back();
        patch.push_back(c);
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int x = c.x + dx, y = c.y + dy;
            if (x < 0 || y < 0 || x >= width_ || y >= height_ || !mask[index(x, y)]) continue;
            mask[index(x, y)] = 0;
            stack.push_back({x, y});
          }
      }
      if (static_cast<int>(patch.size()) >= parameters_.min_cells) patches.push_back(patch);
    }
  return patches;
}

std::optional<CloseLookGoal> CloseLookCoverage::cheapestPatch(const KnownMap& map, const TravelField& travel,
                                                              Point robot) {
  if (!parameters_.enabled) return std::nullopt;
  fit(map);
  const std::vector<std::vector<Cell>> patches = openPatches(map);
  if (patches.empty()) return std::nullopt;
  // Each patch's least travel: never shorter than the straight line to its
  // nearest cell centre, less a map cell's diagonal.
  std::vector<double> least_travel;
  for (const auto& patch : patches) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& c : patch) nearest = std::min(nearest, std::hypot(centreX(c.x) - robot.x, centreY(c.y) - robot.y));
    least_travel.push_back(std::max(0.0, nearest - 1.5 * map.resolution()));
  }
  std::vector<std::optional<CloseLookGoal>> goals(patches.size());
  const auto best = cheapestFirst(std::move(least_travel), [&](std::size_t i, double limit) -> std::optional<double> {
    const Cell* nearest = nullptr;
    double nearest_travel = std::numeric_limits<double>::infinity();
    for (const auto& c : patches[i]) {
      Cell on_map;
      if (!map.cellOf(centreX(c.x), centreY(c.y), on_map) || !map.standable(on_map.x, on_map.y)) continue;
      const double t = travel.within(on_map.x, on_map.y, limit);
      if (std::isfinite(t) && t < nearest_travel) {
        nearest = &c;
        nearest_travel = t;
      }
    }
    if (nearest == nullptr) return std::nullopt;
    goals[i] = goalIn(map, travel, patches[i], *nearest, nearest_travel, robot);
    return goals[i]->travel_m;
  });
  if (!best) return std::nullopt;
  return goals[*best];
}

CloseLookGoal CloseLookCoverage::goalIn(const KnownMap& map, const TravelField& travel, const std::vector<Cell>& patch,
                                        const Cell& nearest, double nearest_travel, Point robot) const {
  // Into the patch: the standable cell near `nearest` with the most of the
  // patch within range (the first of equals, nearest first).
  const double range = parameters_.range_m;
  const Point entry{centreX(nearest.x), centreY(nearest.y)};
  auto within = [&](const Point& from, const Cell& c) {
    return std::hypot(centreX(c.x) - from.x, centreY(c.y) - from.y) <= range;
  };
  CloseLookGoal goal;
  goal.x = entry.x;
  goal.y = entry.y;
  goal.travel_m = nearest_travel;
  goal.size = static_cast<int>(patch.size());
  int most = static_cast<int>(std::count_if(patch.begin(), patch.end(), [&](const Cell& c) { return within(entry, c); }));
  for (const auto& candidate : patch) {
    const Point p{centreX(candidate.x), centreY(candidate.y)};
    if (std::hypot(p.x - entry.x, p.y - entry.y) > parameters_.inward_m) continue;
    Cell on_map;
    if (!map.cellOf(p.x, p.y, on_map) || !map.standable(on_map.x, on_map.y)) continue;
    const int count = static_cast<int>(std::count_if(patch.begin(), patch.end(), [&](const Cell& c) { return within(p, c); }));
    if (count <= most) continue;
    const double t = travel.within(on_map.x, on_map.y, nearest_travel + 2.0 * parameters_.inward_m);
    if (!std::isfinite(t)) continue;
    most = count;
    goal.x = p.x;
    goal.y = p.y;
    goal.travel_m = t;
  }
  // Facing the centre of the patch within range, then turning a quarter at
  // a time to each other quarter around that holds some of it.
  const Point at_goal{goal.x, goal.y};
  double sx = 0, sy = 0;
  int n = 0;
  for (const auto& c : patch)
    if (within(at_goal, c)) {
      sx += centreX(c.x);
      sy += centreY(c.y);
      ++n;
    }
  const bool centred = n == 0 || std::hypot(sx / n - goal.x, sy / n - goal.y) < parameters_.cell_m;
  goal.yaw = centred ? bearingDeg(robot.x, robot.y, goal.x, goal.y) : bearingDeg(goal.x, goal.y, sx / n, sy / n);
  int in_quarter[4] = {0, 0, 0, 0};
  for (const auto& c : patch) {
    const double px = centreX(c.x), py = centreY(c.y);
    if (!within(at_goal, c) || std::hypot(px - goal.x, py - goal.y) < parameters_.cell_m) continue;
    double relative = std::fmod(bearingDeg(goal.x, goal.y, px, py) - goal.yaw + 45.0, 360.0);
    if (relative < 0) relative += 360.0;
    ++in_quarter[std::min(3, static_cast<int>(relative / 90.0))];
  }
  // Quarters 1 to 3: left, behind, right, never more than a quarter turn
  // at once (a half turn has no shorter way). Behind is reached through the
  // left, then on to the right; without it, from the left back through the
  // front to the right.
  const bool left = in_quarter[1] >= parameters_.min_cells, behind = in_quarter[2] >= parameters_.min_cells,
             right = in_quarter[3] >= parameters_.min_cells;
  std::vector<int> quarters;
  if (behind) quarters = right ? std::vector<int>{1, 2, 3} : std::vector<int>{1, 2};
  else if (left && right) quarters = {1, 0, -1};
  else if (left) quarters = {1};
  else if (right) quarters = {-1};
  for (const int quarter : quarters) goal.turns.push_back(std::remainder(goal.yaw + 90.0 * quarter, 360.0));
  return goal;
}

}  // namespace beft::exploration

#include "experts/exploration/frontiers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <beft/obstacle_map_t.hpp>

#include "experts/exploration/cheapest_first.hpp"

namespace beft::exploration {
namespace {

constexpr int kNeighbours4[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};

// Sets the mask's cells whose centres lie within radius of p.
void stampDisc(const KnownMap& map, const Point& p, double radius, std::vector<uint8_t>& mask) {
  const int reach = static_cast<int>(std::ceil(radius / map.resolution())) + 1;
  const double fx = (p.x - map.centreX(0)) / map.resolution(), fy = (p.y - map.centreY(0)) / map.resolution();
  if (!std::isfinite(fx) || !std::isfinite(fy)) return;
  const int cx = static_cast<int>(std::lround(fx)), cy = static_cast<int>(std::lround(fy));
  for (int y = std::max(0, cy - reach); y <= std::min(map.height() - 1, cy + reach); ++y)
    for (int x = std::max(0, cx - reach); x <= std::min(map.width() - 1, cx + reach); ++x)
      if (std::hypot(map.centreX(x) - p.x, map.centreY(y) - p.y) <= radius)
        mask[static_cast<size_t>(y) * map.width() + x] = 1;
}

}  // namespace

void ExplorationMemory::prepare(const KnownMap& map) {
  if (map.width() != width_ || map.height() != height_ || map.resolution() != resolution_ ||
      map.centreX(0) != origin_x_ || map.centreY(0) != origin_y_) {
    width_ = map.width();
    height_ = map.height();
    resolution_ = map.resolution();
    origin_x_ = map.centreX(0);
    origin_y_ = map.centreY(0);
    ignored_unknown_.assign(static_cast<size_t>(width_) * height_, 0);
    ignored_frontier_.assign(static_cast<size_t>(width_) * height_, 0);
    stood_stamped_ = visited_stamped_ = 0;
  }
  for (; stood_stamped_ < stood_.size(); ++stood_stamped_)
    stampDisc(map, stood_[stood_stamped_], parameters_.blind_radius_m, ignored_unknown_);
  for (; visited_stamped_ < visited_.size(); ++visited_stamped_)
    stampDisc(map, visited_[visited_stamped_], parameters_.visited_radius_m, ignored_frontier_);
}

bool isFrontierCell(const KnownMap& map, const ExplorationMemory& memory, int x, int y) {
  if (!map.inside(x, y) || map.at(x, y) != obstacle_map_t::CELL_FREE || memory.frontierIgnored(x, y)) return false;
  for (const auto& n : kNeighbours4) {
    const int nx = x + n[0], ny = y + n[1];
    if (map.inside(nx, ny) && map.at(nx, ny) == obstacle_map_t::CELL_UNKNOWN && !memory.unknownIgnored(nx, ny))
      return true;
  }
  return false;
}

std::vector<std::vector<Cell>> frontierClusters(const KnownMap& map, ExplorationMemory& memory) {
  memory.prepare(map);
  const int w = map.width(), h = map.height();
  std::vector<uint8_t> mask(static_cast<size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) mask[static_cast<size_t>(y) * w + x] = isFrontierCell(map, memory, x, y) ? 1 : 0;
  std::vector<std::vector<Cell>> clusters;
  std::vector<Cell> cluster, stack;
  for (int y0 = 0; y0 < h; ++y0)
    for (int x0 = 0; x0 < w; ++x0) {
      if (!mask[static_cast<size_t>(y0) * w + x0]) continue;
      // Flood one 8-connected frontier, clearing it from the mask.
      cluster.clear();
      stack.assign(1, {x0, y0});
      mask[static_cast<size_t>(y0) * w + x0] = 0;
      while (!stack.empty()) {
        const Cell c = stack.back();
        stack.pop_back();
        cluster.push_back(c);
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int x = c.x + dx, y = c.y + dy;
            if (!map.inside(x, y) || !mask[static_cast<size_t>(y) * w + x]) continue;
            mask[static_cast<size_t>(y) * w + x] = 0;
            stack.push_back({x, y});
          }
      }
      if (static_cast<int>(cluster.size()) >= memory.parameters().min_cells) clusters.push_back(cluster);
    }
  return clusters;
}

namespace {

// The goal of a frontier at its cell `best`, `travel_m` from the robot,
// facing the unknown side of the frontier near it: the sum of the steps from
// its cells into their unknown neighbours.
FrontierGoal goalAt(const KnownMap& map, const ExplorationMemory& memory, const std::vector<Cell>& cluster,
                    const Cell& best, double travel_m) {
  const FrontierParameters& parameters = memory.parameters();
  FrontierGoal goal;
  goal.x = map.centreX(best.x);
  goal.y = map.centreY(best.y);
  goal.travel_m = travel_m;
  goal.size = static_cast<int>(cluster.size());
  goal.cost = goal.travel_m - parameters.size_gain * goal.size * map.resolution();
  double sx = 0, sy = 0;
  for (const auto& c : cluster) {
    if (std::hypot(map.centreX(c.x) - goal.x, map.centreY(c.y) - goal.y) > parameters.facing_radius_m) continue;
    for (const auto& n : kNeighbours4) {
      const int nx = c.x + n[0], ny = c.y + n[1];
      if (map.inside(nx, ny) && map.at(nx, ny) == obstacle_map_t::CELL_UNKNOWN && !memory.unknownIgnored(nx, ny)) {
        sx += n[0];
        sy += n[1];
      }
    }
  }
  goal.yaw = (sx == 0 && sy == 0) ? 0.0 : std::atan2(sy, sx) * 180.0 / M_PI;
  return goal;
}

// The frontier cell the robot reaches soonest within limit_m (the first of
// equals), if any.
const Cell* nearestCell(const KnownMap& map, const TravelField& travel, const std::vector<Cell>& cluster,
                        double limit_m, double& travel_m) {
  const Cell* best = nullptr;
  for (const auto& c : cluster) {
    if (!map.standable(c.x, c.y)) continue;
    const double t = travel.within(c.x, c.y, limit_m);
    if (std::isfinite(t) && (best == nullptr || t < travel_m)) {
      best = &c;
      travel_m = t;
    }
  }
  return best;
}

}  // namespace

std::vector<FrontierGoal> findFrontiers(const KnownMap& map, const TravelField& travel, ExplorationMemory& memory) {
  std::vector<FrontierGoal> goals;
  for (const auto& cluster : frontierClusters(map, memory)) {
    double travel_m = 0;
    const Cell* best = nearestCell(map, travel, cluster, std::numeric_limits<double>::infinity(), travel_m);
    if (best != nullptr) goals.push_back(goalAt(map, memory, cluster, *best, travel_m));
  }
  std::stable_sort(goals.begin(), goals.end(),
                   [](const FrontierGoal& a, const FrontierGoal& b) { return a.cost < b.cost; });
  return goals;
}

std::optional<FrontierGoal> cheapestFrontier(const KnownMap& map, const TravelField& travel,
                                             ExplorationMemory& memory, Point robot) {
  const std::vector<std::vector<Cell>> clusters = frontierClusters(map, memory);
  if (clusters.empty()) return std::nullopt;
  // Each frontier's least possible cost: travel is never shorter than the
  // straight line to its nearest cell, less a cell's diagonal.
  std::vector<double> least_costs, gains;
  for (const auto& cluster : clusters) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& c : cluster)
      nearest = std::min(nearest, std::hypot(map.centreX(c.x) - robot.x, map.centreY(c.y) - robot.y));
    gains.push_back(memory.parameters().size_gain * static_cast<double>(cluster.size()) * map.resolution());
    least_costs.push_back(std::max(0.0, nearest - 1.5 * map.resolution()) - gains.back());
  }
  std::vector<std::optional<FrontierGoal>> goals(clusters.size());
  const auto best = cheapestFirst(std::move(least_costs), [&](std::size_t i, double limit) -> std::optional<double> {
    double travel_m = 0;
    const Cell* cell = nearestCell(map, travel, clusters[i], limit + gains[i], travel_m);
    if (cell == nullptr) return std::nullopt;
    goals[i] = goalAt(map, memory, clusters[i], *cell, travel_m);
    return goals[i]->cost;
  });
  if (!best) return std::nullopt;
  return goals[*best];
}

bool frontierNear(const KnownMap& map, ExplorationMemory& memory, double x, double y, double radius) {
  memory.prepare(map);
  Cell centre;
  if (!map.cellOf(x, y, centre)) return false;
  const int reach = static_cast<int>(std::ceil(radius / map.resolution()));
  for (int cy = centre.y - reach; cy <= centre.y + reach; ++cy)
    for (int cx = centre.x - reach; cx <= centre.x + reach; ++cx)
      if (map.inside(cx, cy) && std::hypot(map.centreX(cx) - x, map.centreY(cy) - y) <= radius &&
          isFrontierCell(map, memory, cx, cy))
        return true;
  return false;
}

}  // namespace beft::exploration

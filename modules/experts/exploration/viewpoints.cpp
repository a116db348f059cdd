#include "experts/exploration/viewpoints.hpp"

#include <algorithm>
#include <cmath>

namespace beft::exploration {

double bearingDeg(double x0, double y0, double x1, double y1) {
  return std::atan2(y1 - y0, x1 - x0) * 180.0 / M_PI;
}

TargetCells targetCells(const KnownMap& map, double target_x, double target_y, const ViewpointParameters& parameters) {
  if (parameters.own_extent_m <= parameters.target_clearance_m) return {};
  // Seeded from half its extent: a car seen from one side only has its near
  // side, not its centre, on the map.
  const double seed = std::max(parameters.target_clearance_m, 0.5 * parameters.own_extent_m);
  return TargetCells(map, target_x, target_y, seed, parameters.own_extent_m);
}

bool inLineOfSight(const KnownMap& map, double x, double y, double target_x, double target_y,
                   const ViewpointParameters& parameters, double* unknown_m, const TargetCells* own) {
  const double dx = target_x - x, dy = target_y - y;
  const double length = std::hypot(dx, dy);
  if (length < 1e-9) return true;
  // Unit normal to the line: the target's sides are +- target_radius along it.
  const double nx = -dy / length, ny = dx / length;
  double unknown = 0;
  for (double side : {0.0, 1.0, -1.0}) {
    const double tx = target_x + side * parameters.target_radius_m * nx;
    const double ty = target_y + side * parameters.target_radius_m * ny;
    const SightLine line = map.sight(x, y, tx, ty, parameters.target_clearance_m, own);
    if (!line.clear) return false;
    if (side == 0.0) unknown = line.unknown_m;
  }
  if (unknown_m != nullptr) *unknown_m = unknown;
  return true;
}

std::optional<Viewpoint> chooseViewpoint(const KnownMap& map, const TravelField& travel, double target_x,
                                         double target_y, const std::vector<Point>& tried,
                                         const ViewpointParameters& parameters, double max_cost,
                                         SightMemory* sights) {
  struct Candidate {
    Cell cell;
    double x, y, travel_m, base_cost;
    size_t slot;  // in the candidate grid
  };
  std::vector<Candidate> candidates;
  const double pitch = std::max(parameters.candidate_spacing_m, map.resolution());
  const int reach = static_cast<int>(std::ceil(parameters.max_distance_m / pitch));
  const size_t slots = static_cast<size_t>(2 * reach + 1) * (2 * reach + 1);
  if (sights != nullptr && sights->clear.size() != slots) {
    sights->clear.assign(slots, -1);
    sights->unknown_m.assign(slots, 0.0);
  }
  for (int j = -reach; j <= reach; ++j) {
    for (int i = -reach; i <= reach; ++i) {
      const double x = target_x + i * pitch, y = target_y + j * pitch;
      const double distance = std::hypot(x - target_x, y - target_y);
      if (distance < parameters.min_distance_m || distance > parameters.max_distance_m) continue;
      Cell cell;
      if (!map.cellOf(x, y, cell) || !map.standable(cell.x, cell.y)) continue;
      // Travel beyond max_cost: the viewpoint would cost more (penalties only add).
      const double travel_m = travel.within(cell.x, cell.y, max_cost);
      if (!std::isfinite(travel_m)) continue;
      const bool near_tried = std::any_of(tried.begin(), tried.end(), [&](const Point& p) {
        return std::hypot(p.x - x, p.y - y) < parameters.tried_radius_m;
      });
      if (near_tried) continue;
      const double base = travel_m + parameters.distance_cost *
                                         std::max(0.0, distance - parameters.preferred_distance_m);
      candidates.push_back({cell, x, y, travel_m, base, static_cast<size_t>(j + reach) * (2 * reach + 1) + (i + reach)});
    }
  }
  // Cheapest first; the line-of-sight test (the costly part) only until no
  // remaining candidate can beat the best found, since penalties only add.
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.base_cost < b.base_cost; });
  std::optional<Viewpoint> best;
  std::optional<TargetCells> own;  // found at the first line of sight asked
  for (const auto& c : candidates) {
    if ((best && c.base_cost >= best->cost) || c.base_cost > max_cost) break;
    double unknown_m = 0;
    if (sights != nullptr && sights->clear[c.slot] >= 0) {
      if (sights->clear[c.slot] == 0) continue;
      unknown_m = sights->unknown_m[c.slot];
    } else {
      if (!own) own = targetCells(map, target_x, target_y, parameters);
      const bool clear = inLineOfSight(map, c.x, c.y, target_x, target_y, parameters, &unknown_m, &*own);
      if (sights != nullptr) {
        sights->clear[c.slot] = clear ? 1 : 0;
        sights->unknown_m[c.slot] = unknown_m;
      }
      if (!clear) continue;
    }
    const double cost = c.base_cost + parameters.unknown_cost * unknown_m;
    if (!best || cost < best->cost)
      best = Viewpoint{c.x, c.y, bearingDeg(c.x, c.y, target_x, target_y), c.travel_m, cost};
  }
  if (best && best->cost > max_cost) return std::nullopt;
  return best;
}

}  // namespace beft::exploration

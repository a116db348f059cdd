#include "lib/scenario/sight_lines.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "lib/scenario/footprint.hpp"

namespace beft::scenario {

namespace {

double topOf(const Object& o) {
  return o.z + (o.visual->shape == Visual::Shape::Box ? o.visual->size_z : o.visual->height);
}

// Narrows [t0, t1] to where p + t d lies within [low, high] on one axis; false when empty.
bool clip(double p, double d, double low, double high, double& t0, double& t1) {
  if (std::abs(d) < 1e-12) return p >= low && p <= high;
  double enter = (low - p) / d, leave = (high - p) / d;
  if (enter > leave) std::swap(enter, leave);
  t0 = std::max(t0, enter);
  t1 = std::min(t1, leave);
  return t0 <= t1;
}

// A half-diagonal: a disc around the centre that holds the footprint.
double reachOf(const Object& o) {
  if (!o.visual) return 0;
  return o.visual->shape == Visual::Shape::Cylinder ? o.visual->radius
                                                    : 0.5 * std::hypot(o.visual->size_x, o.visual->size_y);
}

}  // namespace

bool segmentHitsSolid(const Object& o, const double a[3], const double b[3]) {
  if (!o.visual) return false;
  double t0 = 0, t1 = 1;
  if (!clip(a[2], b[2] - a[2], o.z, topOf(o), t0, t1)) return false;
  if (o.visual->shape == Visual::Shape::Box) {
    // Into the box's frame (Liang-Barsky on each axis, as the slab test).
    const double yaw = o.yaw * M_PI / 180.0, c = std::cos(yaw), s = std::sin(yaw);
    const double ax = c * (a[0] - o.x) + s * (a[1] - o.y), ay = -s * (a[0] - o.x) + c * (a[1] - o.y);
    const double bx = c * (b[0] - o.x) + s * (b[1] - o.y), by = -s * (b[0] - o.x) + c * (b[1] - o.y);
    const double hx = o.visual->size_x / 2, hy = o.visual->size_y / 2;
    return clip(ax, bx - ax, -hx, hx, t0, t1) && clip(ay, by - ay, -hy, hy, t0, t1);
  }
  // A cylinder: where the segment's ground track is within the radius.
  const double dx = b[0] - a[0], dy = b[1] - a[1], fx = a[0] - o.x, fy = a[1] - o.y;
  const double qa = dx * dx + dy * dy, qb = 2 * (fx * dx + fy * dy);
  const double qc = fx * fx + fy * fy - o.visual->radius * o.visual->radius;
  if (qa < 1e-12) return qc <= 0;
  const double discriminant = qb * qb - 4 * qa * qc;
  if (discriminant < 0) return false;
  const double root = std::sqrt(discriminant);
  t0 = std::max(t0, (-qb - root) / (2 * qa));
  t1 = std::min(t1, (-qb + root) / (2 * qa));
  return t0 <= t1;
}

bool mustBeSeen(const Object& object) { return object.label != "wall"; }

SightLines::SightLines(const Scenario& scenario, const ReachabilityOptions& reach, const SightOptions& sight)
    : scenario_(scenario), space_(scenario, reach), sight_(sight) {}

std::optional<Place> SightLines::placeThatSees(const Object& target) const {
  // The objects that could stand between: within reach of the farthest line,
  // but not one the target stands in or on (a siren's pole).
  std::vector<const Object*> near;
  for (const Object& o : scenario_.objects)
    if (&o != &target && o.visual && std::hypot(o.x - target.x, o.y - target.y) <= sight_.max_distance + reachOf(o) &&
        distanceToFootprint(o, target.x, target.y) > 0)
      near.push_back(&o);
  // Points of its body: its centre at half its height and near its top (below the eye).
  const double top = target.visual ? topOf(target) : target.z + 1.0;
  const double points[2][3] = {{target.x, target.y, 0.5 * (target.z + top)},
                               {target.x, target.y, std::min(sight_.eye_height, target.z + 0.9 * (top - target.z))}};
  // Nearest places first: the usual answer is found at once.
  std::vector<std::pair<double, Place>> places;
  const int steps = static_cast<int>(std::ceil(sight_.max_distance / sight_.spacing));
  for (int j = -steps; j <= steps; ++j)
    for (int i = -steps; i <= steps; ++i) {
      const double x = target.x + i * sight_.spacing, y = target.y + j * sight_.spacing;
      const double distance = std::hypot(x - target.x, y - target.y);
      if (distance < sight_.min_distance || distance > sight_.max_distance || !space_.isReachableAt(x, y)) continue;
      places.push_back({distance, {x, y}});
    }
  std::stable_sort(places.begin(), places.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [distance, place] : places) {
    const double eye[3] = {place.x, place.y, sight_.eye_height};
    for (const auto& point : points) {
      const bool blocked = std::any_of(near.begin(), near.end(),
                                       [&](const Object* o) { return segmentHitsSolid(*o, eye, point); });
      if (!blocked) return place;
    }
  }
  return std::nullopt;
}

std::vector<std::string> unseeableObjects(const Scenario& scenario, const ReachabilityOptions& reach,
                                          const SightOptions& sight) {
  const SightLines lines(scenario, reach, sight);
  std::vector<std::string> unseeable;
  for (const Object& object : scenario.objects)
    if (mustBeSeen(object) && !lines.placeThatSees(object)) unseeable.push_back(object.id);
  return unseeable;
}

}  // namespace beft::scenario

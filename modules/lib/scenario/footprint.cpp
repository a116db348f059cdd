#include "lib/scenario/footprint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace beft::scenario {

double distanceToFootprint(const Object& object, double px, double py) {
  if (!object.visual) return std::numeric_limits<double>::infinity();
  const Visual& visual = *object.visual;
  const double dx = px - object.x;
  const double dy = py - object.y;
  if (visual.shape == Visual::Shape::Cylinder) {
    return std::max(0.0, std::hypot(dx, dy) - visual.radius);
  }
  // Express the point in the box's own frame, then measure to the rectangle.
  const double yaw = object.yaw * M_PI / 180.0;
  const double local_x = std::cos(yaw) * dx + std::sin(yaw) * dy;
  const double local_y = -std::sin(yaw) * dx + std::cos(yaw) * dy;
  const double outside_x = std::max(0.0, std::abs(local_x) - visual.size_x / 2);
  const double outside_y = std::max(0.0, std::abs(local_y) - visual.size_y / 2);
  return std::hypot(outside_x, outside_y);
}

}  // namespace beft::scenario

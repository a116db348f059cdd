#include "tools/figure/scene_grid.hpp"

#include <cmath>

namespace beft::figure {

planners::GridMap groundTruthGrid(const scenario::Scenario& scenario) {
  const double cell = scenario.world.resolution;
  const int width = static_cast<int>(std::lround(scenario.world.width / cell));
  const int height = static_cast<int>(std::lround(scenario.world.height / cell));
  planners::GridMap grid(width, height);
  for (const auto& object : scenario.objects) {
    if (!object.visual || object.label == "person") continue;
    const auto& visual = *object.visual;
    const double yaw = object.yaw * M_PI / 180.0;
    const double c = std::cos(yaw), s = std::sin(yaw);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        // The cell centre in the object's frame.
        const double dx = (x + 0.5) * cell - object.x, dy = (y + 0.5) * cell - object.y;
        const double u = c * dx + s * dy, v = -s * dx + c * dy;
        const bool inside = visual.shape == scenario::Visual::Shape::Box
                                ? std::abs(u) <= 0.5 * visual.size_x && std::abs(v) <= 0.5 * visual.size_y
                                : u * u + v * v <= visual.radius * visual.radius;
        if (inside) grid.setBlocked(x, y);
      }
    }
  }
  return grid;
}

}  // namespace beft::figure

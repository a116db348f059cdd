#include "planners/bench/scenario_raster.hpp"

#include "lib/scenario/footprint.hpp"

#include <algorithm>
#include <cmath>

namespace beft::planners {

ScenarioMap rasterizeScenario(const beft::scenario::Scenario& scenario) {
  const double res = scenario.world.resolution;
  const int width = std::max(1, static_cast<int>(std::ceil(scenario.world.width / res - 1e-9)));
  const int height = std::max(1, static_cast<int>(std::ceil(scenario.world.height / res - 1e-9)));
  ScenarioMap out{scenario.name, GridMap(width, height), res, {scenario.robot.x / res, scenario.robot.y / res},
                  scenario.robot.radius / res};
  for (const auto& object : scenario.objects) {
    if (!object.visual) continue;
    // Only cells near the object can be inside its footprint.
    const auto& v = *object.visual;
    const double reach = v.shape == beft::scenario::Visual::Shape::Cylinder
                             ? v.radius
                             : 0.5 * std::hypot(v.size_x, v.size_y);
    const int x0 = std::max(0, static_cast<int>(std::floor((object.x - reach) / res)) - 1);
    const int x1 = std::min(width - 1, static_cast<int>(std::ceil((object.x + reach) / res)) + 1);
    const int y0 = std::max(0, static_cast<int>(std::floor((object.y - reach) / res)) - 1);
    const int y1 = std::min(height - 1, static_cast<int>(std::ceil((object.y + reach) / res)) + 1);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        if (beft::scenario::distanceToFootprint(object, (x + 0.5) * res, (y + 0.5) * res) <= 0.5 * res) {
          out.grid.setBlocked(x, y);
        }
      }
    }
  }
  return out;
}

}  // namespace beft::planners

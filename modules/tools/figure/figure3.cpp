#include "tools/figure/figure3.hpp"

#include <stdexcept>

#include "lib/scenario/load_scenario.hpp"
#include "planners/path_tools.hpp"
#include "planners/planner_factory.hpp"
#include "planners/potential_field_planner.hpp"
#include "planners/render.hpp"
#include "tools/figure/scene_grid.hpp"
#include "lib/common/whole_file.hpp"

namespace beft::figure {

Figure3Result drawFigure3(const Figure3Options& options) {
  const scenario::Scenario scene = scenario::loadScenario(options.scenario_path);
  const double cell = scene.world.resolution;
  auto map = std::make_shared<planners::PlanningMap>(groundTruthGrid(scene), scene.robot.radius / cell);
  const planners::Point2 goal{options.goal.x / cell, options.goal.y / cell};

  planners::PlannerConfig config;
  config.seed = options.seed;
  Figure3Result result;
  std::vector<planners::DrawnPlan> plans;
  std::vector<planners::Path> particles;
  for (const auto& start_m : options.starts) {
    const planners::Point2 start{start_m.x / cell, start_m.y / cell};
    auto planner = planners::makePlanner("pf-paper", config);
    planner->setup(map);
    const planners::PlanResult plan = planner->solve(start, goal, planners::Deadline::after(30.0));
    if (!plan.success)
      throw std::runtime_error("from (" + std::to_string(start_m.x) + ", " + std::to_string(start_m.y) + "): " +
                               plan.message);
    const auto& pf = dynamic_cast<const planners::PotentialFieldPlanner&>(*planner);
    particles.insert(particles.end(), pf.particleTraces().begin(), pf.particleTraces().end());
    result.lengths_m.push_back(plan.length() * cell);
    result.waypoints.push_back(plan.path.size());
    result.arrived.push_back(static_cast<int>(planner->statistics().at("arrived")));
    // h_W has a waypoint every cell: a dot and an arrow every 0.5 m keep it legible.
    plans.push_back({plan.path, planners::travelHeadings(plan.path, 0.0), start,
                     static_cast<size_t>(std::max(1.0, 0.5 / cell))});
  }
  planners::RenderOptions render;
  render.y_up = true;
  const std::string partial = partialPathFor(options.out);
  planners::writePng(partial, planners::renderPlans(*map, plans, particles, goal, render));
  commitPartial(partial, options.out);
  return result;
}

}  // namespace beft::figure

#include "planners/planner_factory.hpp"

#include "planners/astar_planner.hpp"
#include "planners/ompl_planner.hpp"

#include <stdexcept>

namespace beft::planners {

std::unique_ptr<Planner> makePlanner(const std::string& name, const PlannerConfig& config) {
  std::unique_ptr<Planner> planner;
  if (name == "astar") {
    planner = std::make_unique<AStarPlanner>();
  } else if (name == "pf" || name == "pf-paper" || name == "pf-geodesic") {
    PotentialFieldParams params;
    if (name == "pf-geodesic") params.target = TargetPotential::Geodesic;
    for (const auto& [key, value] : config.pf_params) params.set(key, value);
    auto pf = std::make_unique<PotentialFieldPlanner>(params);
    if (name == "pf-paper") pf->setName(name);
    planner = std::move(pf);
  } else if (name.rfind("ompl:", 0) == 0) {
    planner = std::make_unique<OmplPlanner>(name.substr(5));
  } else {
    std::string known;
    for (const auto& n : plannerNames()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown planner '" + name + "' (known: " + known + ")");
  }
  planner->setSeed(config.seed);
  planner->setTighten(config.tighten && name != "pf-paper");
  return planner;
}

std::vector<std::string> plannerNames() {
  std::vector<std::string> names{"astar", "pf", "pf-paper", "pf-geodesic"};
  for (const auto& n : omplPlannerNames()) names.push_back("ompl:" + n);
  return names;
}

std::vector<std::string> benchmarkPlannerNames() {
  return {"astar",        "pf",                    "pf-geodesic",  "ompl:RRTConnect",
          "ompl:RRTstar", "ompl:InformedRRTstar", "ompl:BITstar", "ompl:PRMstar"};
}

std::pair<std::string, std::string> splitParameter(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw std::invalid_argument("parameter '" + text + "' is not name=value");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

}  // namespace beft::planners

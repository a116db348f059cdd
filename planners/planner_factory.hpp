// Planners by name, as chosen on command lines and in plan requests:
//   astar                  octile A* (optimal on the grid)
//   pf                     the paper's potential-field planner (Euclidean target potential)
//   pf-geodesic            the same with the geodesic (wavefront) target potential
//   ompl:NAME              an OMPL planner, e.g. ompl:RRTConnect, ompl:RRTstar,
//                          ompl:InformedRRTstar, ompl:BITstar, ompl:PRMstar
#pragma once

#include "planners/planner.hpp"
#include "planners/potential_field_planner.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace beft::planners {

struct PlannerConfig {
  uint64_t seed = 1;
  // Potential-field parameters as name=value overrides (PotentialFieldParams::set).
  std::vector<std::pair<std::string, std::string>> pf_params;
  // The shortening every planner's path gets (tightenPath: sparse, taut
  // waypoints). "pf-paper" always goes without: the robot traces the
  // winning particle's path h_W itself, as in the paper.
  bool tighten = true;
};

// Names: astar, pf (the paper's fields, its path tightened), pf-paper (the
// paper's planner as printed: h_W itself), pf-geodesic, ompl:NAME.
// Throws std::invalid_argument for an unknown name or a bad parameter.
std::unique_ptr<Planner> makePlanner(const std::string& name, const PlannerConfig& config = {});

// Every accepted name (OMPL ones as ompl:NAME).
std::vector<std::string> plannerNames();

// The planners the benchmark compares by default.
std::vector<std::string> benchmarkPlannerNames();

// Splits "name=value"; throws std::invalid_argument without '='.
std::pair<std::string, std::string> splitParameter(const std::string& text);

}  // namespace beft::planners

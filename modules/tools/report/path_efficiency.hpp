// Path efficiency per victim: the SPL idea (success weighted by path length,
// Anderson et al. 2018, "On Evaluation of Embodied Navigation Agents", as
// SoundSpaces' AudioGoal uses it) applied to each person of a mission.
//
// For a person found, l = the shortest path from the robot's start to the
// nearest viewpoint of the person on the ground truth, p = the distance the
// robot drove from the start until the person was found, and the efficiency
// is l / max(l, p), in [0, 1]. The mission's mean is over every person
// present, a person missed counting 0 (SPL = 1/N sum_i S_i l_i / max(p_i, l_i)).
//
// The ground truth is the scenario's obstacle map (every object with a
// visual, planners/bench/scenario_raster.hpp); the robot may stand where the
// exploration expert's known map allows with the planner's inflation
// (robot radius plus margin). A viewpoint is a standable cell within the
// camera's range from which the exploration expert's sight test sees the
// person, where the person truly was when found
// (experts/exploration/viewpoints.hpp); the nearest is the one of least
// octile travel over standable cells (one wavefront from the start), and l
// is the length of the planners' A* path to it on the same map inflated as
// the planner inflates it (planners/astar_planner.hpp, pulled taut as every
// planner's path is), or that travel if A* finds none. The person's own
// footprint does not count as hiding it. The sight test is that of a flat
// map: every object blocks the view, low ones too, so l may be longer than a
// camera looking over low debris needs (the efficiency is then capped at 1).
#pragma once

#include <optional>

#include "lib/report/run_record.hpp"
#include "lib/report/run_scoring.hpp"
#include "lib/scenario/scenario.hpp"

namespace beft::report {

struct PathEfficiencyOptions {
  double inflation_m = 0.5;  // the planner's obstacle inflation (mission.xml's planner_inflation) [m]
};

// l / max(l, p); 1 when both are 0.
double pathEfficiency(double shortest_m, double driven_m);

// Fills each victim's shortest_path_m, driven_m and path_efficiency (none
// for a person no viewpoint of which can be reached) and the report's
// path_efficiency_mean.
void scorePathEfficiency(const RunRecord& record, const scenario::Scenario& scenario,
                         const PathEfficiencyOptions& options, RunReport& report);

}  // namespace beft::report

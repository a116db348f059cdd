// Operations on planned paths shared by every planner and the benchmark:
// collision check, shortcutting to sparse waypoints, headings and quality
// figures (length, turning, clearance).
#pragma once

#include "planners/geometry.hpp"
#include "planners/planning_map.hpp"

#include <vector>

namespace beft::planners {

// Every segment free on the inflated map (a single point: that point free).
bool pathFree(const PlanningMap& map, const Path& path);

// Sparse waypoints along a free path: from each kept waypoint, jump to the
// farthest later point still in line of sight on the inflated map. Never
// longer than the input (triangle inequality) and free when the input is.
Path shortcutPath(const PlanningMap& map, const Path& path);

// Pulls a free path taut against the inflated map: drops a waypoint when its
// neighbours see each other, otherwise cuts its corner by the widest free cut
// (binary search along both segments), for `passes` sweeps; then shortcuts.
// Never longer than the input and free when the input is.
Path tightenPath(const PlanningMap& map, const Path& path, int passes = 6);

// Drops repeated points (closer than 1e-9 cells).
Path removeDuplicatePoints(const Path& path);

// Sum of the absolute heading changes at the interior vertices [rad].
double totalTurning(const Path& path);

// Smallest clearance to a raw obstacle along the path, sampled every `step`
// cells [cells].
double minClearance(const PlanningMap& map, const Path& path, double step = 0.25);

// Heading of travel at each waypoint [rad, CCW from +x in the path's frame]:
// the direction of the segment leaving it; the last waypoint gets
// goal_heading. A single point gets goal_heading.
std::vector<double> travelHeadings(const Path& path, double goal_heading);

}  // namespace beft::planners

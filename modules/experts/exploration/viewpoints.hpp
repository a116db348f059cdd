// Choosing where to look at a hypothesis from (section "Active exploration"):
// a pose from which the known obstacle map says the target would be in line
// of sight, that the robot can stand on and reach, not too close nor too far,
// preferring short travel and lines of sight through known free space.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "experts/exploration/known_map.hpp"
#include "experts/exploration/target_cells.hpp"

namespace beft::exploration {

struct ViewpointParameters {
  double min_distance_m = 1.5;     // closest viewpoint to the target [m]
  double max_distance_m = 6.0;     // farthest (well within camera range) [m]
  double preferred_distance_m = 4.0;  // beyond this each metre costs distance_cost
  double distance_cost = 0.5;      // [m of travel per m beyond preferred]
  double candidate_spacing_m = 0.25;  // viewpoints are tried on a grid of this pitch
  double target_radius_m = 0.3;    // half width of the target: the sight lines to its
                                   // two sides must be clear too
  double target_clearance_m = 0.5; // occupied cells this close to the target are its own
  // How far from its position a target's body may reach [m]: beyond
  // target_clearance_m, the occupied cells connected to it this close are its
  // own too (target_cells.hpp). The explorer sets a car's.
  double own_extent_m = 0.5;
  double unknown_cost = 2.0;       // [m of travel per m of sight line through unknown cells]
  double tried_radius_m = 1.0;     // a viewpoint this close to a tried one is not tried again
};

struct Viewpoint {
  double x = 0, y = 0;    // [m]
  double yaw = 0;         // facing the target [deg]
  double travel_m = 0;    // travel from the robot on the known map [m]
  double cost = 0;        // travel plus penalties [m]
};

struct Point {
  double x = 0, y = 0;
};

// True when the target would be in line of sight from (x, y): the centre line
// and the lines to both sides of the target cross no occupied cell.
bool inLineOfSight(const KnownMap& map, double x, double y, double target_x, double target_y,
                   const ViewpointParameters& parameters, double* unknown_m = nullptr,
                   const TargetCells* own = nullptr);

// The target's own cells as `parameters` say how far they reach; none when
// own_extent_m is within target_clearance_m.
TargetCells targetCells(const KnownMap& map, double target_x, double target_y, const ViewpointParameters& parameters);

// What the lines of sight from one target's candidate viewpoints showed, for
// asking about the same target on the same map again (a search with a
// higher max_cost): one entry per candidate of its grid.
struct SightMemory {
  std::vector<int8_t> clear;       // -1 not looked at yet, 0 blocked, 1 clear
  std::vector<double> unknown_m;   // of the clear ones
};

// The cheapest viewpoint, or none. tried: viewpoints already used for this
// target. With max_cost, only a viewpoint costing at most that: none then
// means every viewpoint costs more (the travel field is searched no farther).
// sights, when given, keeps what was looked at for the next call.
std::optional<Viewpoint> chooseViewpoint(const KnownMap& map, const TravelField& travel, double target_x,
                                         double target_y, const std::vector<Point>& tried,
                                         const ViewpointParameters& parameters,
                                         double max_cost = std::numeric_limits<double>::infinity(),
                                         SightMemory* sights = nullptr);

// Bearing from (x0, y0) to (x1, y1), CCW from +x [deg].
double bearingDeg(double x0, double y0, double x1, double y1);

}  // namespace beft::exploration

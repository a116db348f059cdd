// Where a sound comes from, from the directions it was heard in at several
// places the robot passed: the point nearest, in the weighted least-squares
// sense, to every bearing line. One bearing gives a direction only; lines from places
// far enough apart (seen from the source, at angles that differ) give the
// distance too.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

namespace beft::audio {

struct BearingLine {
  Eigen::Vector2d from;  // head position when heard, world frame [m]
  double bearing_deg;    // world direction it was heard in, CCW from +x [deg]
};

struct TriangulationLimits {
  // The lines must cross at an angle: the smaller eigenvalue of
  // mean (I - d d^T), the mean sin^2 of each line's angle to the best
  // fitting direction, at least this: about 6 degrees rms, twice the error
  // of a clear bearing, so noise alone does not make a crossing.
  double min_spread = 0.012;
  double max_range_m = 60;  // a crossing farther than this from the last place is not believed
  int reweighting_passes = 2;  // passes of the crossing with lines weighted by lineWeight (0: every line alike)
  double min_range_m = 0.5;    // nearer lines weigh as if this far [m]
  // A bearing's error grows in proportion to the distance beyond this: the
  // farther the source, the fainter against the others and the echoes [m].
  double error_growth_range_m = 4;
};

// The least-squares crossing of the lines, if they cross well enough and in
// front of (not behind) most of them.
std::optional<Eigen::Vector2d> triangulate(const std::vector<BearingLine>& lines,
                                           const TriangulationLimits& limits = TriangulationLimits{});

// The weight of a bearing line at `range_m` from a crossing, 1 / (r s)^2:
// an angular error misses by itself times r, and the error itself grows by
// s = max(1, r / error_growth_range_m).
double lineWeight(double range_m, const TriangulationLimits& limits);

// How far off a crossing may be when each bearing up close errs by
// bearing_sd_deg [m]: the root of the trace of the inverse of the lines'
// mean information (each line's normal n: n n^T lineWeight(r)), as for one
// bearing-only fix. The mean, not the sum: the bearings of one source err
// alike (a reflection, another source near it), so more lines from the same
// places do not make a better fix; lines far from the source, or from places
// that see it at nearly one angle, do make a worse one. Infinite for lines
// that do not cross.
double crossingError(const std::vector<BearingLine>& lines, const Eigen::Vector2d& crossing, double bearing_sd_deg,
                     const TriangulationLimits& limits = TriangulationLimits{});

}  // namespace beft::audio

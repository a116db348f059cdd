// Where a sound comes from, from the directions it was heard in at several
// places the robot passed: the point nearest, in the least-squares sense, to
// every bearing line. One bearing gives a direction only; lines from places
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
};

// The least-squares crossing of the lines, if they cross well enough and in
// front of (not behind) most of them.
std::optional<Eigen::Vector2d> triangulate(const std::vector<BearingLine>& lines,
                                           const TriangulationLimits& limits = TriangulationLimits{});

}  // namespace beft::audio

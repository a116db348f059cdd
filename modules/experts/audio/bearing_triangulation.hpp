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
  // The robust crossing: a line agrees with a point when the direction from
  // its place to the point is within inlier_deg of its bearing; at least
  // min_inliers lines, and min_inlier_share of them, must agree.
  double inlier_deg = 4;
  int min_inliers = 3;
  double min_inlier_share = 0.3;
};

// The least-squares crossing of the lines, if they cross well enough and in
// front of (not behind) most of them.
std::optional<Eigen::Vector2d> triangulate(const std::vector<BearingLine>& lines,
                                           const TriangulationLimits& limits = TriangulationLimits{});

// The crossing of the largest subset of lines that agree on one point, then
// crossed by least squares (triangulate): lines of another source, or of an
// echo, given to this one by mistake are left out. Every pair of lines that
// crosses in front of both is a candidate point, as in RANSAC (Fischler &
// Bolles 1981) but exhaustively, the lines being few (at most a few dozen).
std::optional<Eigen::Vector2d> triangulateRobustly(const std::vector<BearingLine>& lines,
                                                   const TriangulationLimits& limits = TriangulationLimits{});

}  // namespace beft::audio

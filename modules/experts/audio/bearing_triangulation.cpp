#include "experts/audio/bearing_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace beft::audio {
namespace {

Eigen::Vector2d unitOf(double bearing_deg) {
  const double radians = bearing_deg * M_PI / 180.0;
  return {std::cos(radians), std::sin(radians)};
}

}  // namespace

std::optional<Eigen::Vector2d> triangulate(const std::vector<BearingLine>& lines, const TriangulationLimits& limits) {
  if (lines.size() < 2) return std::nullopt;
  Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
  Eigen::Vector2d right = Eigen::Vector2d::Zero();
  for (const auto& line : lines) {
    if (!line.from.allFinite() || !std::isfinite(line.bearing_deg)) return std::nullopt;
    const Eigen::Vector2d d = unitOf(line.bearing_deg);
    const Eigen::Matrix2d across = Eigen::Matrix2d::Identity() - d * d.transpose();  // distance to the line
    normal += across;
    right += across * line.from;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(normal);
  if (eigen.eigenvalues().minCoeff() / static_cast<double>(lines.size()) < limits.min_spread) return std::nullopt;
  Eigen::Vector2d crossing = normal.inverse() * right;
  // A bearing that errs by an angle misses the source by that angle times
  // its distance: each line is weighted by lineWeight (r its distance to the
  // crossing so far), so that lines heard up close are not outweighed by
  // the many heard from far away, whose errors move the crossing far.
  for (int pass = 0; pass < limits.reweighting_passes; ++pass) {
    Eigen::Matrix2d weighted_normal = Eigen::Matrix2d::Zero();
    Eigen::Vector2d weighted_right = Eigen::Vector2d::Zero();
    for (const auto& line : lines) {
      const Eigen::Vector2d d = unitOf(line.bearing_deg);
      const Eigen::Matrix2d across = Eigen::Matrix2d::Identity() - d * d.transpose();
      const double weight = lineWeight((crossing - line.from).norm(), limits);
      weighted_normal += across * weight;
      weighted_right += across * line.from * weight;
    }
    const Eigen::Vector2d reweighted = weighted_normal.inverse() * weighted_right;
    if (!reweighted.allFinite()) break;
    crossing = reweighted;
  }
  int in_front = 0;
  for (const auto& line : lines)
    if ((crossing - line.from).dot(unitOf(line.bearing_deg)) > 0) ++in_front;
  if (2 * in_front <= static_cast<int>(lines.size())) return std::nullopt;
  if ((crossing - lines.back().from).norm() > limits.max_range_m) return std::nullopt;
  return crossing;
}

double lineWeight(double range_m, const TriangulationLimits& limits) {
  const double range = std::max(limits.min_range_m, range_m);
  const double growth = limits.error_growth_range_m > 0 ? std::max(1.0, range / limits.error_growth_range_m) : 1.0;
  return 1.0 / (range * range * growth * growth);
}

double crossingError(const std::vector<BearingLine>& lines, const Eigen::Vector2d& crossing, double bearing_sd_deg,
                     const TriangulationLimits& limits) {
  if (lines.empty() || !crossing.allFinite()) return std::numeric_limits<double>::infinity();
  Eigen::Matrix2d information = Eigen::Matrix2d::Zero();
  for (const auto& line : lines) {
    const Eigen::Vector2d d = unitOf(line.bearing_deg);
    const Eigen::Vector2d normal(-d.y(), d.x());
    information += normal * normal.transpose() * lineWeight((crossing - line.from).norm(), limits);
  }
  information /= static_cast<double>(lines.size());
  const double determinant = information.determinant();
  if (!(determinant > 1e-12 * information.trace() * information.trace())) return std::numeric_limits<double>::infinity();
  const double error = bearing_sd_deg * M_PI / 180.0 * std::sqrt(information.inverse().trace());
  return std::isfinite(error) ? error : std::numeric_limits<double>::infinity();
}

}  // namespace beft::audio

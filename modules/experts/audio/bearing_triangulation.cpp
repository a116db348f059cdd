#include "experts/audio/bearing_triangulation.hpp"

#include <cmath>

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
  const Eigen::Vector2d crossing = normal.inverse() * right;
  int in_front = 0;
  for (const auto& line : lines)
    if ((crossing - line.from).dot(unitOf(line.bearing_deg)) > 0) ++in_front;
  if (2 * in_front <= static_cast<int>(lines.size())) return std::nullopt;
  if ((crossing - lines.back().from).norm() > limits.max_range_m) return std::nullopt;
  return crossing;
}

}  // namespace beft::audio

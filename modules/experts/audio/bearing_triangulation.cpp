#include "experts/audio/bearing_triangulation.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace beft::audio {
namespace {

Eigen::Vector2d unitOf(double bearing_deg) {
  const double radians = bearing_deg * M_PI / 180.0;
  return {std::cos(radians), std::sin(radians)};
}

// Where two lines cross, if in front of both.
std::optional<Eigen::Vector2d> crossingOf(const BearingLine& a, const BearingLine& b) {
  const Eigen::Vector2d da = unitOf(a.bearing_deg), db = unitOf(b.bearing_deg);
  const double determinant = da.x() * (-db.y()) - da.y() * (-db.x());
  if (std::abs(determinant) < 1e-9) return std::nullopt;
  const Eigen::Vector2d gap = b.from - a.from;
  const double along_a = (gap.x() * (-db.y()) - gap.y() * (-db.x())) / determinant;
  const double along_b = (da.x() * gap.y() - da.y() * gap.x()) / determinant;
  if (along_a <= 0 || along_b <= 0) return std::nullopt;
  return a.from + along_a * da;
}

bool agrees(const BearingLine& line, const Eigen::Vector2d& point, double inlier_deg) {
  const Eigen::Vector2d towards = point - line.from;
  if (towards.norm() < 1e-6) return true;
  const double bearing = std::atan2(towards.y(), towards.x()) * 180.0 / M_PI;
  double difference = std::fmod(std::abs(bearing - line.bearing_deg), 360.0);
  if (difference > 180) difference = 360 - difference;
  return difference <= inlier_deg;
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

namespace beft::audio {

std::optional<Eigen::Vector2d> triangulateRobustly(const std::vector<BearingLine>& lines,
                                                   const TriangulationLimits& limits) {
  if (lines.size() < 2) return std::nullopt;
  std::vector<BearingLine> best;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    for (std::size_t j = i + 1; j < lines.size(); ++j) {
      const auto point = crossingOf(lines[i], lines[j]);
      if (!point || (*point - lines.back().from).norm() > limits.max_range_m) continue;
      std::vector<BearingLine> agreeing;
      for (const auto& line : lines)
        if (agrees(line, *point, limits.inlier_deg)) agreeing.push_back(line);
      if (agreeing.size() > best.size()) best = std::move(agreeing);
    }
  }
  const auto enough = static_cast<std::size_t>(std::max<double>(limits.min_inliers,
                                                                limits.min_inlier_share * lines.size()));
  if (best.size() < enough) return std::nullopt;
  return triangulate(best, limits);
}

}  // namespace beft::audio

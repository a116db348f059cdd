#include "lib/scene/acoustic_occlusion.hpp"

#include <cmath>

#include "lib/scene/object_geometry.hpp"

namespace beft::audio {

namespace {
constexpr double kInset = 0.9;             // sample points pulled 10% towards the centre
constexpr double kLowFraction = 0.05;      // of the height, from the base
constexpr double kHighFraction = 0.95;
}  // namespace

std::vector<Eigen::Vector3d> sourceSamplePoints(const scene_object_t& source) {
  if (!geometry::hasVisual(source)) return {Eigen::Vector3d(source.x, source.y, source.z)};
  const double yaw = source.yaw * M_PI / 180.0;
  const Eigen::Vector2d axis_x(std::cos(yaw), std::sin(yaw));
  const Eigen::Vector2d axis_y(-std::sin(yaw), std::cos(yaw));
  std::vector<Eigen::Vector2d> rim;  // horizontal offsets from the centre
  if (source.shape == scene_object_t::SHAPE_BOX) {
    const double hx = kInset * 0.5 * source.size_x, hy = kInset * 0.5 * source.size_y;
    for (double sx : {-1.0, 1.0})
      for (double sy : {-1.0, 1.0}) rim.push_back(sx * hx * axis_x + sy * hy * axis_y);
  } else {
    const double r = kInset * (source.radius > 0 ? source.radius : 0.5 * source.size_x);
    rim = {r * axis_x, r * axis_y, -r * axis_x, -r * axis_y};
  }
  const Eigen::Vector3d centre = geometry::objectCentre(source);
  std::vector<Eigen::Vector3d> points{centre};
  for (double fraction : {kLowFraction, kHighFraction}) {
    const double z = source.z + fraction * source.size_z;
    for (const auto& offset : rim) points.emplace_back(source.x + offset.x(), source.y + offset.y(), z);
  }
  return points;
}

double acousticOcclusion(const camera::SceneGeometry& scene, int source_index,
                         const std::vector<Eigen::Vector3d>& sample_points, const Eigen::Vector3d& left_ear,
                         const Eigen::Vector3d& right_ear) {
  if (sample_points.empty()) return 0.0;
  int blocked = 0;
  for (const auto& point : sample_points) {
    blocked += camera::segmentBlocked(scene, point, left_ear, source_index) ? 1 : 0;
    blocked += camera::segmentBlocked(scene, point, right_ear, source_index) ? 1 : 0;
  }
  return 100.0 * blocked / (2.0 * sample_points.size());
}

}  // namespace beft::audio

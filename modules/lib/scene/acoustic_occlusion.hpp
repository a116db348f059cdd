// Acoustic occlusion O_a (spec/model.md): the share of straight lines from
// sample points of a source to the two ears that pass through another
// object's solid (boxes by yaw, cylinders, with their heights).
//
// Sample points: a source with a visual is sampled at 9 points: its centre
// and 8 points near the corners of its shape (a box: its corners; a cylinder:
// 4 points on its rim, at yaw + 0, 90, 180, 270 deg), at 5% and 95% of its
// height and pulled 10% towards the centre so every point lies inside the
// source. A source without a visual is one point at (x, y, z).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <beft/scene_object_t.hpp>

#include "lib/scene/scene_geometry.hpp"

namespace beft::audio {

std::vector<Eigen::Vector3d> sourceSamplePoints(const scene_object_t& source);

// O_a in percent: 100 * blocked lines / (2 * points). Lines through the source
// itself (object index source_index) do not count as blocked.
double acousticOcclusion(const camera::SceneGeometry& scene, int source_index,
                         const std::vector<Eigen::Vector3d>& sample_points, const Eigen::Vector3d& left_ear,
                         const Eigen::Vector3d& right_ear);

}  // namespace beft::audio

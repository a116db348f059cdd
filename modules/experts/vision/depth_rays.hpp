// Depth image to rays for the obstacle map: each pixel of a DEPTH_MM16 frame
// becomes the ray through its centre (camera::pixelRay, the renderer's own
// convention) with the z-depth of its return.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include <beft/camera_frame_t.hpp>

#include "lib/scene/camera_model.hpp"
#include "experts/vision/obstacle_mapper.hpp"

namespace beft::vision {

// The rays of a DEPTH_MM16 frame, computed when asked for (a whole image of
// rays is 32 bytes a pixel): ray (u, v) = rowStart(v) + columnStep(u), the
// same sum depthRays stores. Throws std::invalid_argument on a frame that is
// not DEPTH_MM16 or has a wrong size. Keeps a reference to the frame.
class DepthFrameRays {
 public:
  explicit DepthFrameRays(const camera_frame_t& depth);
  int width() const { return depth_.width; }
  int height() const { return depth_.height; }
  bool level() const { return depth_.cam_pitch == 0.0; }  // the camera model has no roll
  Eigen::Vector3d origin() const { return {depth_.cam_x, depth_.cam_y, depth_.cam_z}; }
  Eigen::Vector3d rowStart(int v) const;
  const Eigen::Vector3d& columnStep(int u) const { return column_step_[u]; }
  // Depth of pixel (u, v) in metres, 0 = no return.
  double depth(int u, int v) const {
    return depthOfPixel(depth_.data.data(), static_cast<std::size_t>(v) * depth_.width + u);
  }
  // The same from the frame's bytes: pixel p (row-major), little-endian millimetres.
  const uint8_t* depthBytes() const { return depth_.data.data(); }
  static double depthOfPixel(const uint8_t* bytes, std::size_t p) {
    return (bytes[2 * p] | (static_cast<unsigned>(bytes[2 * p + 1]) << 8)) * 1e-3;
  }

 private:
  const camera_frame_t& depth_;
  camera::CameraFrame frame_;
  Eigen::Vector3d corner_;
  std::vector<Eigen::Vector3d> column_step_;
};

// The frame's rays; t = depth in metres (0: no return). Throws
// std::invalid_argument on a frame that is not DEPTH_MM16 or has a wrong size.
DepthImage depthRays(const camera_frame_t& depth);
// The same into an existing image (reuses its memory).
void depthRays(const camera_frame_t& depth, DepthImage& image);

}  // namespace beft::vision

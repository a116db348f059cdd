#include "experts/vision/depth_rays.hpp"

#include <stdexcept>
#include <string>

#include "lib/scene/camera_model.hpp"

namespace beft::vision {

namespace {

const camera_frame_t& checkedDepthFrame(const camera_frame_t& depth) {
  if (depth.encoding != camera_frame_t::ENCODING_DEPTH_MM16)
    throw std::invalid_argument("depth frame has encoding " + std::to_string(depth.encoding) +
                                ", expected DEPTH_MM16");
  if (depth.compression != camera_frame_t::COMPRESSION_NONE)
    throw std::invalid_argument("depth frame still compressed (camera::decodeCameraFrame unpacks it)");
  if (depth.width <= 0 || depth.height <= 0) throw std::invalid_argument("depth frame has no pixels");
  const std::size_t pixels = static_cast<std::size_t>(depth.width) * static_cast<std::size_t>(depth.height);
  if (depth.data.size() != 2 * pixels)
    throw std::invalid_argument("depth frame holds " + std::to_string(depth.data.size()) + " bytes, expected " +
                                std::to_string(2 * pixels));
  return depth;
}

}  // namespace

DepthFrameRays::DepthFrameRays(const camera_frame_t& depth)
    : depth_(checkedDepthFrame(depth)), frame_(camera::cameraOfFrame(depth)) {
  // pixelRay is affine in (u, v): ray(u, v) = ray(0, v) + (ray(u, 0) - ray(0, 0)).
  corner_ = camera::pixelRay(frame_, 0, 0);
  column_step_.resize(depth.width);
  for (int u = 0; u < depth.width; ++u) column_step_[u] = camera::pixelRay(frame_, u, 0) - corner_;
}

Eigen::Vector3d DepthFrameRays::rowStart(int v) const { return camera::pixelRay(frame_, 0, v); }

DepthImage depthRays(const camera_frame_t& depth) {
  DepthImage image;
  depthRays(depth, image);
  return image;
}

void depthRays(const camera_frame_t& depth, DepthImage& image) {
  const DepthFrameRays rays(depth);
  image.width = rays.width();
  image.height = rays.height();
  image.level = rays.level();
  image.rays.resize(static_cast<std::size_t>(image.width) * image.height);
  for (int v = 0; v < image.height; ++v) {
    const Eigen::Vector3d row_start = rays.rowStart(v);
    for (int u = 0; u < image.width; ++u) {
      DepthRay& ray = image.rays[static_cast<std::size_t>(v) * image.width + u];
      ray.direction = row_start + rays.columnStep(u);
      ray.t = rays.depth(u, v);
    }
  }
}

}  // namespace beft::vision

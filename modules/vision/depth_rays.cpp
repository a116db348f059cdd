#include "depth_rays.hpp"

#include <stdexcept>
#include <string>

#include "camera_model.hpp"

namespace beft::vision {

DepthImage depthRays(const camera_frame_t& depth) {
  DepthImage image;
  depthRays(depth, image);
  return image;
}

void depthRays(const camera_frame_t& depth, DepthImage& image) {
  if (depth.encoding != camera_frame_t::ENCODING_DEPTH_MM16)
    throw std::invalid_argument("depth frame has encoding " + std::to_string(depth.encoding) +
                                ", expected DEPTH_MM16");
  if (depth.width <= 0 || depth.height <= 0) throw std::invalid_argument("depth frame has no pixels");
  const std::size_t pixels = static_cast<std::size_t>(depth.width) * static_cast<std::size_t>(depth.height);
  if (depth.data.size() != 2 * pixels)
    throw std::invalid_argument("depth frame holds " + std::to_string(depth.data.size()) + " bytes, expected " +
                                std::to_string(2 * pixels));
  const camera::CameraFrame frame(camera::cameraOfFrame(depth));
  // pixelRay is affine in (u, v): ray(u, v) = ray(0, v) + (ray(u, 0) - ray(0, 0)).
  const Eigen::Vector3d corner = camera::pixelRay(frame, 0, 0);
  std::vector<Eigen::Vector3d> column_step(depth.width);
  for (int u = 0; u < depth.width; ++u) column_step[u] = camera::pixelRay(frame, u, 0) - corner;
  image.width = depth.width;
  image.height = depth.height;
  image.level = depth.cam_pitch == 0.0;  // the camera model has no roll
  image.rays.resize(pixels);
  for (int v = 0; v < depth.height; ++v) {
    const Eigen::Vector3d row_start = camera::pixelRay(frame, 0, v);
    for (int u = 0; u < depth.width; ++u) {
      const std::size_t p = static_cast<std::size_t>(v) * depth.width + u;
      const unsigned millimetres = depth.data[2 * p] | (static_cast<unsigned>(depth.data[2 * p + 1]) << 8);
      image.rays[p].direction = row_start + column_step[u];
      image.rays[p].t = millimetres * 1e-3;
    }
  }
}

}  // namespace beft::vision

#include "depth_rays.hpp"

#include <stdexcept>
#include <string>

#include "camera_model.hpp"

namespace beft::vision {

std::vector<DepthRay> depthRays(const camera_frame_t& depth) {
  if (depth.encoding != camera_frame_t::ENCODING_DEPTH_MM16)
    throw std::invalid_argument("depth frame has encoding " + std::to_string(depth.encoding) +
                                ", expected DEPTH_MM16");
  if (depth.width <= 0 || depth.height <= 0) throw std::invalid_argument("depth frame has no pixels");
  const std::size_t pixels = static_cast<std::size_t>(depth.width) * static_cast<std::size_t>(depth.height);
  if (depth.data.size() != 2 * pixels)
    throw std::invalid_argument("depth frame holds " + std::to_string(depth.data.size()) + " bytes, expected " +
                                std::to_string(2 * pixels));
  const camera::CameraFrame frame(camera::cameraOfFrame(depth));
  std::vector<DepthRay> rays(pixels);
  for (int v = 0; v < depth.height; ++v) {
    for (int u = 0; u < depth.width; ++u) {
      const std::size_t p = static_cast<std::size_t>(v) * depth.width + u;
      const unsigned millimetres = depth.data[2 * p] | (static_cast<unsigned>(depth.data[2 * p + 1]) << 8);
      rays[p].direction = camera::pixelRay(frame, u, v);
      rays[p].t = millimetres * 1e-3;
    }
  }
  return rays;
}

}  // namespace beft::vision

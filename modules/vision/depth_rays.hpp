// Depth image to rays for the obstacle map: each pixel of a DEPTH_MM16 frame
// becomes the ray through its centre (camera::pixelRay, the renderer's own
// convention) with the z-depth of its return.
#pragma once

#include <vector>

#include <beft/camera_frame_t.hpp>

#include "obstacle_mapper.hpp"

namespace beft::vision {

// Rays in row-major pixel order; t = depth in metres (0: no return). Throws
// std::invalid_argument on a frame that is not DEPTH_MM16 or has a wrong size.
std::vector<DepthRay> depthRays(const camera_frame_t& depth);

}  // namespace beft::vision

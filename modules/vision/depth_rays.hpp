// Depth image to rays for the obstacle map: each pixel of a DEPTH_MM16 frame
// becomes the ray through its centre (camera::pixelRay, the renderer's own
// convention) with the z-depth of its return.
#pragma once

#include <vector>

#include <beft/camera_frame_t.hpp>

#include "obstacle_mapper.hpp"

namespace beft::vision {

// The frame's rays; t = depth in metres (0: no return). Throws
// std::invalid_argument on a frame that is not DEPTH_MM16 or has a wrong size.
DepthImage depthRays(const camera_frame_t& depth);
// The same into an existing image (reuses its memory).
void depthRays(const camera_frame_t& depth, DepthImage& image);

}  // namespace beft::vision

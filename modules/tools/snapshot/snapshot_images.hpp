// Pictures of the world for people: the camera frame (colour, colour-mapped
// depth, instance ids) and a top-down map of the scene with the robot.
#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "lib/scene/ray_caster.hpp"
#include "sim/world/world_simulation.hpp"

namespace beft::snapshot {

// The camera's colour image (BGR), each pixel a zoom x zoom block.
cv::Mat colorImage(const camera::RenderedFrame& frame, int zoom);
// Depth colour-mapped from near (red) to the camera's range (blue); no
// return is black. With a colour scale bar underneath.
cv::Mat depthImage(const camera::RenderedFrame& frame, int zoom);
// Each object seen in its own colour, its id written on it; ground and sky
// black.
cv::Mat instanceImage(const camera::RenderedFrame& frame, const world::WorldSimulation& world, int zoom);
// The whole world from above: 1 m grid, objects by category with their ids,
// sound sources, paths, the robot with its heading and the camera's field of
// view. pixels_per_metre <= 0 picks one for about 1200 px on the long side.
cv::Mat topDownImage(const world::WorldSimulation& world, double pixels_per_metre);

}  // namespace beft::snapshot

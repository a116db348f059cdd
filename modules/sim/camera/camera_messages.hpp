// Camera frames as LCM messages (camera_frame_t on CAMERA_COLOR, CAMERA_DEPTH,
// CAMERA_INSTANCE) and the helpers that read them back.
//
// RGB8: 3 bytes per pixel. DEPTH_MM16: z-depth in millimetres as little-endian
// uint16, 0 = no return (nothing within range, or deeper than 65.535 m).
// INSTANCE16: little-endian uint16, 0 = no object (ground or sky), v > 0 shows
// the object instance_ids[v - 1] = ground-truth object index v - 1.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <beft/camera_frame_t.hpp>

#include "ray_caster.hpp"

namespace beft::camera {

struct CameraMessages {
  beft::camera_frame_t color, depth, instance;
};

// Fills the three messages of one frame. object_ids: the ground-truth object
// ids in list order (carried by the instance message).
void encodeCameraMessages(const RenderedFrame& frame, int64_t utime, int64_t tick,
                          const std::vector<std::string>& object_ids, CameraMessages& out);

// Renders straight into the three messages, row by row (no whole-image
// frame in between): the same messages as render + encodeCameraMessages.
void renderCameraMessages(RayCaster& caster, const SceneGeometry& scene, const Camera& camera, int64_t utime,
                          int64_t tick, const std::vector<std::string>& object_ids, CameraMessages& out);

// Whether a received frame is self-consistent (known encoding, positive size,
// data_size matching width * height * bytes per pixel). why says what is not.
bool validCameraFrame(const beft::camera_frame_t& frame, std::string* why = nullptr);

// Readers for valid frames; (u, v) must be inside the image.
double depthAt(const beft::camera_frame_t& depth_frame, int u, int v);     // [m], 0 = no return
int objectAt(const beft::camera_frame_t& instance_frame, int u, int v);    // object index, -1 = none

}  // namespace beft::camera

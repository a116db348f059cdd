// Camera frames as LCM messages (camera_frame_t on CAMERA_COLOR, CAMERA_DEPTH,
// CAMERA_INSTANCE) holding their pixels, and the helpers that read them back.
// On the wire they travel compressed: frame_compressor.hpp packs them,
// frame_decoding.hpp turns a received one back into this form.
//
// RGB8: 3 bytes per pixel. DEPTH_MM16: z-depth in millimetres as little-endian
// uint16, 0 = no return (nothing within range, or deeper than 65.535 m).
// INSTANCE16: little-endian uint16, 0 = no object (ground or sky), v > 0 shows
// the object instance_ids[v - 1]. The frame lists only the objects it shows,
// in the ground truth's order.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <beft/camera_frame_t.hpp>

#include "lib/scene/ray_caster.hpp"

namespace beft::camera {

struct CameraMessages {
  beft::camera_frame_t color, depth, instance;
};

// Fills the three messages of one frame. object_ids: the ground-truth object
// ids in list order (the instance message carries those the frame shows).
void encodeCameraMessages(const RenderedFrame& frame, int64_t utime, int64_t tick,
                          const std::vector<std::string>& object_ids, CameraMessages& out);

// Renders straight into the three messages, row by row (no whole-image
// frame in between): the same messages as render + encodeCameraMessages.
void renderCameraMessages(RayCaster& caster, const SceneGeometry& scene, const Camera& camera, int64_t utime,
                          int64_t tick, const std::vector<std::string>& object_ids, CameraMessages& out);

// Frames of more pixels than this are refused by every reader: a received
// header must not make it allocate whatever it claims (3840 x 2160 fits).
constexpr int64_t kMaxFramePixels = int64_t{8} << 20;

// Bytes per pixel of an ENCODING_*, 0 for an unknown one.
int bytesPerPixel(int8_t encoding);

// The bytes of the frame's pixels (width * height * bytes per pixel) if its
// header is self-consistent (known encoding, positive size of at most
// kMaxFramePixels, num_ids matching instance_ids), else -1 and why says what
// is not. Whatever data holds.
int64_t pixelBytesOf(const beft::camera_frame_t& frame, std::string* why = nullptr);

// Whether a frame holds its pixels and is self-consistent (header as above,
// COMPRESSION_NONE, data_size matching the pixel bytes). why says what is not.
// A received frame becomes one through decodeCameraFrame (frame_decoding.hpp).
bool validCameraFrame(const beft::camera_frame_t& frame, std::string* why = nullptr);

// Readers for valid frames; (u, v) must be inside the image.
double depthAt(const beft::camera_frame_t& depth_frame, int u, int v);     // [m], 0 = no return
int instanceAt(const beft::camera_frame_t& instance_frame, int u, int v);  // index into instance_ids, -1 = none

}  // namespace beft::camera

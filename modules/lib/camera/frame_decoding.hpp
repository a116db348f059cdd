// The one way a received camera frame becomes pixels. Every reader of
// CAMERA_* messages (the vision expert, the render tool, tests, ...) goes
// through here, after the message guard: the guard checks the layout and
// that `compression` is a declared value; this checks what the payload
// claims and unpacks it.
//
// A frame is untrusted bytes. It is refused, with the reason, when its header
// is inconsistent (camera_messages.hpp: pixelBytesOf), when it holds more or
// fewer pixel bytes than width x height x bytes per pixel, when a compressed
// payload is not exactly one zstd frame declaring that many bytes, carries no
// checksum, or does not decompress to them intact. Memory is sized from the
// header, never from the payload, and never beyond kMaxFramePixels.
#pragma once

#include <string>

#include <beft/camera_frame_t.hpp>

namespace beft::camera {

// pixels := received with its pixels in data (COMPRESSION_NONE), a frame
// validCameraFrame accepts. False, pixels untouched and why set, if refused.
bool decodeCameraFrame(const beft::camera_frame_t& received, beft::camera_frame_t& pixels,
                       std::string* why = nullptr);

// The same in place: frame is left as it was when refused.
bool decodeCameraFrame(beft::camera_frame_t& frame, std::string* why = nullptr);

}  // namespace beft::camera

#include "camera_messages.hpp"

#include <algorithm>
#include <cmath>

namespace beft::camera {

namespace {

void fillHeader(const RenderedFrame& frame, int64_t utime, int64_t tick, int8_t encoding,
                beft::camera_frame_t& message) {
  const CameraPose& pose = frame.camera.pose;
  message.utime = utime;
  message.tick = tick;
  message.encoding = encoding;
  message.width = frame.width;
  message.height = frame.height;
  message.fov = frame.camera.intrinsics.fov_deg;
  message.range = frame.camera.intrinsics.range;
  message.cam_x = pose.x;
  message.cam_y = pose.y;
  message.cam_z = pose.z;
  message.cam_yaw = pose.yaw_deg;
  message.cam_pitch = pose.pitch_deg;
  message.num_ids = 0;
  message.instance_ids.clear();
}

inline void putUint16(uint8_t* data, size_t pixel, uint16_t value) {
  data[2 * pixel] = static_cast<uint8_t>(value & 0xFF);
  data[2 * pixel + 1] = static_cast<uint8_t>(value >> 8);
}

inline uint16_t getUint16(const beft::camera_frame_t& frame, int u, int v) {
  const size_t pixel = static_cast<size_t>(v) * frame.width + u;
  return static_cast<uint16_t>(frame.data[2 * pixel] | (frame.data[2 * pixel + 1] << 8));
}

}  // namespace

void encodeCameraMessages(const RenderedFrame& frame, int64_t utime, int64_t tick,
                          const std::vector<std::string>& object_ids, CameraMessages& out) {
  const size_t pixels = static_cast<size_t>(frame.width) * frame.height;

  fillHeader(frame, utime, tick, beft::camera_frame_t::ENCODING_RGB8, out.color);
  out.color.data.assign(frame.rgb.begin(), frame.rgb.begin() + 3 * pixels);
  out.color.data_size = static_cast<int32_t>(out.color.data.size());

  fillHeader(frame, utime, tick, beft::camera_frame_t::ENCODING_DEPTH_MM16, out.depth);
  out.depth.data.resize(2 * pixels);
  // Raw pointers: byte stores through the vector would make the compiler
  // reload its data pointer for every pixel.
  uint8_t* depth_bytes = out.depth.data.data();
  const float* depth = frame.depth.data();
  for (size_t p = 0; p < pixels; ++p) {
    // Rounded to the nearest millimetre (depths are never negative).
    const double millimetres = static_cast<double>(depth[p]) * 1000.0 + 0.5;
    const uint16_t value = (millimetres >= 1 && millimetres < 65536) ? static_cast<uint16_t>(millimetres) : 0;
    putUint16(depth_bytes, p, value);
  }
  out.depth.data_size = static_cast<int32_t>(out.depth.data.size());

  fillHeader(frame, utime, tick, beft::camera_frame_t::ENCODING_INSTANCE16, out.instance);
  out.instance.instance_ids = object_ids;
  out.instance.num_ids = static_cast<int32_t>(object_ids.size());
  out.instance.data.resize(2 * pixels);
  uint8_t* instance_bytes = out.instance.data.data();
  const int32_t* objects = frame.object.data();
  const int32_t id_count = static_cast<int32_t>(std::min<size_t>(object_ids.size(), 65535));
  for (size_t p = 0; p < pixels; ++p) {
    const int32_t object = objects[p];
    putUint16(instance_bytes, p, object >= 0 && object < id_count ? static_cast<uint16_t>(object + 1) : 0);
  }
  out.instance.data_size = static_cast<int32_t>(out.instance.data.size());
}

bool validCameraFrame(const beft::camera_frame_t& frame, std::string* why) {
  const auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  int bytes_per_pixel = 0;
  switch (frame.encoding) {
    case beft::camera_frame_t::ENCODING_RGB8:
      bytes_per_pixel = 3;
      break;
    case beft::camera_frame_t::ENCODING_DEPTH_MM16:
    case beft::camera_frame_t::ENCODING_INSTANCE16:
      bytes_per_pixel = 2;
      break;
    default:
      return fail("unknown encoding " + std::to_string(frame.encoding));
  }
  if (frame.width <= 0 || frame.height <= 0) {
    return fail("image size " + std::to_string(frame.width) + "x" + std::to_string(frame.height));
  }
  const int64_t expected = static_cast<int64_t>(frame.width) * frame.height * bytes_per_pixel;
  if (frame.data_size != expected || static_cast<int64_t>(frame.data.size()) != expected) {
    return fail("data_size " + std::to_string(frame.data_size) + " but " + std::to_string(expected) +
                " expected");
  }
  if (frame.encoding == beft::camera_frame_t::ENCODING_INSTANCE16 &&
      frame.num_ids != static_cast<int32_t>(frame.instance_ids.size())) {
    return fail("num_ids does not match instance_ids");
  }
  return true;
}

double depthAt(const beft::camera_frame_t& depth_frame, int u, int v) {
  return getUint16(depth_frame, u, v) / 1000.0;
}

int objectAt(const beft::camera_frame_t& instance_frame, int u, int v) {
  return static_cast<int>(getUint16(instance_frame, u, v)) - 1;
}

}  // namespace beft::camera

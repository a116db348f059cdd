#include "lib/camera/camera_messages.hpp"

#include <algorithm>
#include <cmath>

namespace beft::camera {

namespace {

void fillHeader(const Camera& camera, int64_t utime, int64_t tick, int8_t encoding, beft::camera_frame_t& message) {
  const CameraPose& pose = camera.pose;
  message.utime = utime;
  message.tick = tick;
  message.encoding = encoding;
  message.compression = beft::camera_frame_t::COMPRESSION_NONE;
  message.width = std::max(camera.intrinsics.width, 0);
  message.height = std::max(camera.intrinsics.height, 0);
  message.fov = camera.intrinsics.fov_deg;
  message.range = camera.intrinsics.range;
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

// The headers and data sizes of a frame's three messages. The instance
// message lists its objects once its pixels are in (listShownObjects).
void prepareMessages(const Camera& camera, int64_t utime, int64_t tick, CameraMessages& out) {
  fillHeader(camera, utime, tick, beft::camera_frame_t::ENCODING_RGB8, out.color);
  fillHeader(camera, utime, tick, beft::camera_frame_t::ENCODING_DEPTH_MM16, out.depth);
  fillHeader(camera, utime, tick, beft::camera_frame_t::ENCODING_INSTANCE16, out.instance);
  const size_t pixels = static_cast<size_t>(out.color.width) * out.color.height;
  out.color.data.resize(3 * pixels);
  out.depth.data.resize(2 * pixels);
  out.instance.data.resize(2 * pixels);
  out.color.data_size = static_cast<int32_t>(out.color.data.size());
  out.depth.data_size = static_cast<int32_t>(out.depth.data.size());
  out.instance.data_size = static_cast<int32_t>(out.instance.data.size());
}

// Pixels [first, first + count) of the three messages; an instance pixel
// holds its object's index + 1 (0 for none or an object without an id) until
// listShownObjects renumbers them. Raw pointers: byte stores through the
// vectors would make the compiler reload their data pointers for every pixel.
void encodePixels(size_t first, size_t count, const float* depth, const int32_t* object, const uint8_t* rgb,
                  int32_t id_count, CameraMessages& out) {
  std::copy_n(rgb, 3 * count, out.color.data.data() + 3 * first);
  uint8_t* depth_bytes = out.depth.data.data();
  for (size_t i = 0; i < count; ++i) {
    // Rounded to the nearest millimetre (depths are never negative).
    const double millimetres = static_cast<double>(depth[i]) * 1000.0 + 0.5;
    const uint16_t value = (millimetres >= 1 && millimetres < 65536) ? static_cast<uint16_t>(millimetres) : 0;
    putUint16(depth_bytes, first + i, value);
  }
  uint8_t* instance_bytes = out.instance.data.data();
  id_count = std::min(id_count, 65535);
  for (size_t i = 0; i < count; ++i) {
    const int32_t index = object[i];
    putUint16(instance_bytes, first + i, index >= 0 && index < id_count ? static_cast<uint16_t>(index + 1) : 0);
  }
}

class MessageRowWriter : public FrameRowWriter {
 public:
  MessageRowWriter(int32_t id_count, CameraMessages& out) : id_count_(id_count), out_(out) {}
  void writeRow(int v, const float* depth, const int32_t* object, const uint8_t* rgb) override {
    const size_t width = static_cast<size_t>(out_.color.width);
    encodePixels(static_cast<size_t>(v) * width, width, depth, object, rgb, id_count_, out_);
  }

 private:
  int32_t id_count_;
  CameraMessages& out_;
};

int32_t idCount(const std::vector<std::string>& object_ids) {
  return static_cast<int32_t>(std::min<size_t>(object_ids.size(), 65535));
}

// The instance frame lists only the objects it shows, in the ground truth's
// order, and its pixels are renumbered to match: at hundreds of objects the
// whole list was most of the message, at every tick.
void listShownObjects(const std::vector<std::string>& object_ids, beft::camera_frame_t& instance) {
  uint8_t* const bytes = instance.data.data();
  const size_t pixels = instance.data.size() / 2;
  std::vector<uint16_t> renumbered(static_cast<size_t>(idCount(object_ids)) + 1, 0);  // old value -> new value
  for (size_t p = 0; p < pixels; ++p) renumbered[bytes[2 * p] | (bytes[2 * p + 1] << 8)] = 1;
  instance.instance_ids.clear();
  for (size_t value = 1; value < renumbered.size(); ++value) {
    if (renumbered[value] == 0) continue;
    instance.instance_ids.push_back(object_ids[value - 1]);
    renumbered[value] = static_cast<uint16_t>(instance.instance_ids.size());
  }
  renumbered[0] = 0;
  instance.num_ids = static_cast<int32_t>(instance.instance_ids.size());
  for (size_t p = 0; p < pixels; ++p) putUint16(bytes, p, renumbered[bytes[2 * p] | (bytes[2 * p + 1] << 8)]);
}

}  // namespace

void encodeCameraMessages(const RenderedFrame& frame, int64_t utime, int64_t tick,
                          const std::vector<std::string>& object_ids, CameraMessages& out) {
  Camera camera = frame.camera;
  camera.intrinsics.width = frame.width;
  camera.intrinsics.height = frame.height;
  prepareMessages(camera, utime, tick, out);
  encodePixels(0, static_cast<size_t>(frame.width) * frame.height, frame.depth.data(), frame.object.data(),
               frame.rgb.data(), idCount(object_ids), out);
  listShownObjects(object_ids, out.instance);
}

void renderCameraMessages(RayCaster& caster, const SceneGeometry& scene, const Camera& camera, int64_t utime,
                          int64_t tick, const std::vector<std::string>& object_ids, CameraMessages& out) {
  prepareMessages(camera, utime, tick, out);
  MessageRowWriter writer(idCount(object_ids), out);
  caster.render(scene, camera, writer);
  listShownObjects(object_ids, out.instance);
}

int bytesPerPixel(int8_t encoding) {
  switch (encoding) {
    case beft::camera_frame_t::ENCODING_RGB8:
      return 3;
    case beft::camera_frame_t::ENCODING_DEPTH_MM16:
    case beft::camera_frame_t::ENCODING_INSTANCE16:
      return 2;
    default:
      return 0;
  }
}

int64_t pixelBytesOf(const beft::camera_frame_t& frame, std::string* why) {
  const auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return int64_t{-1};
  };
  const int bytes_per_pixel = bytesPerPixel(frame.encoding);
  if (bytes_per_pixel == 0) return fail("unknown encoding " + std::to_string(frame.encoding));
  if (frame.width <= 0 || frame.height <= 0) {
    return fail("image size " + std::to_string(frame.width) + "x" + std::to_string(frame.height));
  }
  const int64_t pixels = static_cast<int64_t>(frame.width) * frame.height;
  if (pixels > kMaxFramePixels) {
    return fail("image size " + std::to_string(frame.width) + "x" + std::to_string(frame.height) + " above the " +
                std::to_string(kMaxFramePixels) + " pixels accepted");
  }
  if (frame.encoding == beft::camera_frame_t::ENCODING_INSTANCE16 &&
      frame.num_ids != static_cast<int32_t>(frame.instance_ids.size())) {
    return fail("num_ids does not match instance_ids");
  }
  return pixels * bytes_per_pixel;
}

bool validCameraFrame(const beft::camera_frame_t& frame, std::string* why) {
  const int64_t expected = pixelBytesOf(frame, why);
  if (expected < 0) return false;
  const auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (frame.compression != beft::camera_frame_t::COMPRESSION_NONE) {
    return fail("compressed (compression " + std::to_string(frame.compression) + "): decode it first");
  }
  if (frame.data_size != expected || static_cast<int64_t>(frame.data.size()) != expected) {
    return fail("data_size " + std::to_string(frame.data_size) + " but " + std::to_string(expected) +
                " expected");
  }
  return true;
}

double depthAt(const beft::camera_frame_t& depth_frame, int u, int v) {
  return getUint16(depth_frame, u, v) / 1000.0;
}

int instanceAt(const beft::camera_frame_t& instance_frame, int u, int v) {
  return static_cast<int>(getUint16(instance_frame, u, v)) - 1;
}

}  // namespace beft::camera

#include "lib/wire/earlier_layouts.hpp"

#include <cstddef>

#include "lib/wire/embedded_schemas.hpp"
#include "lib/wire/lcm_schema.hpp"

namespace beft::wire {

namespace {

// camera_frame_t before `compression` (its members only: they make the fingerprint).
const char* const kCameraFrameWithoutCompression = R"(package beft;
struct camera_frame_t
{
    int64_t utime;
    int64_t tick;
    int8_t  encoding;
    int32_t width;
    int32_t height;
    double  fov;
    double  range;
    double  cam_x;
    double  cam_y;
    double  cam_z;
    double  cam_yaw;
    double  cam_pitch;
    int32_t num_ids;
    string  instance_ids[num_ids];
    int32_t data_size;
    byte    data[data_size];
}
)";

// `compression` follows the fingerprint, utime, tick and encoding.
constexpr std::size_t kCompressionOffset = 8 + 8 + 8 + 1;

struct CameraFrameUpgrade {
  uint64_t earlier = 0, today = 0;
};

uint64_t fingerprintIn(const std::string& file, const std::string& text) {
  LcmTypeSet types;
  types.addSchema(file, text);
  types.finalize();
  return types.fingerprint("beft.camera_frame_t");
}

const CameraFrameUpgrade& cameraFrameUpgrade() {
  static const CameraFrameUpgrade upgrade = [] {
    CameraFrameUpgrade fingerprints;
    fingerprints.earlier = fingerprintIn("camera_frame_t.lcm (without compression)", kCameraFrameWithoutCompression);
    for (const EmbeddedSchema& schema : embeddedLcmSchemas())
      if (schema.file == "camera_frame_t.lcm") fingerprints.today = fingerprintIn(schema.file, schema.text);
    return fingerprints;
  }();
  return upgrade;
}

uint64_t readFingerprint(const std::vector<uint8_t>& data) {
  uint64_t value = 0;
  for (std::size_t i = 0; i < 8; ++i) value = (value << 8) | data[i];
  return value;
}

void writeFingerprint(uint64_t value, std::vector<uint8_t>& data) {
  for (std::size_t i = 0; i < 8; ++i) data[i] = static_cast<uint8_t>(value >> (56 - 8 * i));
}

}  // namespace

bool upgradeEarlierLayout(std::vector<uint8_t>& data) {
  if (data.size() < kCompressionOffset) return false;
  const CameraFrameUpgrade& camera = cameraFrameUpgrade();
  if (readFingerprint(data) != camera.earlier || camera.today == 0) return false;
  writeFingerprint(camera.today, data);
  data.insert(data.begin() + kCompressionOffset, uint8_t{0});  // COMPRESSION_NONE
  return true;
}

}  // namespace beft::wire

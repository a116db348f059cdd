#include "lib/wire/earlier_layouts.hpp"

#include <cstddef>
#include <string>

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

// run_beacon_t before `description` and `started_utime`.
const char* const kRunBeaconWithoutDescription = R"(package beft;
struct run_beacon_t
{
    int64_t utime;
    int64_t run_id;
    string  host;
    int32_t pid;
    int64_t tick;
}
)";

// fire_t before `after_sender` and `after_frontier`.
const char* const kFireWithoutFrontier = R"(package beft;
struct fire_t
{
    int64_t utime;
    string  expert;
    string  transition;
    int64_t tick;
    int64_t firing_id;
}
)";

// done_t before `sender` and the channels published.
const char* const kDoneWithoutPublished = R"(package beft;
struct done_t
{
    int64_t utime;
    string  expert;
    int64_t tick;
    int64_t firing_id;
    int8_t  outcome;
    string  message;
    double  duration;
    const int8_t OUTCOME_OK = 0, OUTCOME_FAILED = 1;
}
)";

constexpr std::size_t kAtEnd = static_cast<std::size_t>(-1);

// A type that gained members: its layout before, and where the new members
// go, as zero bytes (what each of them means when not known).
struct LayoutChange {
  const char* file;  // today's .lcm file
  const char* type;  // "beft.camera_frame_t"
  const char* earlier;
  std::size_t insert_at;  // [bytes] from the message's start, fingerprint included; kAtEnd: after the last
  std::size_t added_bytes;
};

const LayoutChange kChanges[] = {
    // `compression` follows the fingerprint, utime, tick and encoding; 0 = COMPRESSION_NONE.
    {"camera_frame_t.lcm", "beft.camera_frame_t", kCameraFrameWithoutCompression, 8 + 8 + 8 + 1, 1},
    // `description` and `started_utime` close the message; 0 = not known.
    {"run_beacon_t.lcm", "beft.run_beacon_t", kRunBeaconWithoutDescription, kAtEnd, 8 + 8},
    // `after_sender` and `after_frontier` close the message; 0 = comes after nothing.
    {"fire_t.lcm", "beft.fire_t", kFireWithoutFrontier, kAtEnd, 8 + 8},
    // `sender` and `num_published` close the message; 0 = not known, nothing listed.
    {"done_t.lcm", "beft.done_t", kDoneWithoutPublished, kAtEnd, 8 + 4},
};

struct Upgrade {
  uint64_t earlier = 0, today = 0;
  const LayoutChange* change = nullptr;
};

uint64_t fingerprintIn(const std::string& file, const std::string& text, const std::string& type) {
  LcmTypeSet types;
  types.addSchema(file, text);
  types.finalize();
  return types.fingerprint(type);
}

const std::vector<Upgrade>& upgrades() {
  static const std::vector<Upgrade> all = [] {
    std::vector<Upgrade> found;
    for (const LayoutChange& change : kChanges) {
      Upgrade upgrade;
      upgrade.change = &change;
      upgrade.earlier = fingerprintIn(std::string(change.file) + " (earlier)", change.earlier, change.type);
      for (const EmbeddedSchema& schema : embeddedLcmSchemas())
        if (schema.file == change.file) upgrade.today = fingerprintIn(schema.file, schema.text, change.type);
      if (upgrade.today != 0) found.push_back(upgrade);
    }
    return found;
  }();
  return all;
}

constexpr std::size_t kFingerprintBytes = 8;

uint64_t readFingerprint(const std::vector<uint8_t>& data) {
  uint64_t value = 0;
  for (std::size_t i = 0; i < kFingerprintBytes; ++i) value = (value << 8) | data[i];
  return value;
}

void writeFingerprint(uint64_t value, std::vector<uint8_t>& data) {
  for (std::size_t i = 0; i < kFingerprintBytes; ++i) data[i] = static_cast<uint8_t>(value >> (56 - 8 * i));
}

}  // namespace

bool upgradeEarlierLayout(std::vector<uint8_t>& data) {
  if (data.size() < kFingerprintBytes) return false;
  const uint64_t fingerprint = readFingerprint(data);
  for (const Upgrade& upgrade : upgrades()) {
    if (fingerprint != upgrade.earlier) continue;
    const std::size_t at = upgrade.change->insert_at == kAtEnd ? data.size() : upgrade.change->insert_at;
    if (data.size() < at) return false;
    writeFingerprint(upgrade.today, data);
    data.insert(data.begin() + static_cast<std::ptrdiff_t>(at), upgrade.change->added_bytes, uint8_t{0});
    return true;
  }
  return false;
}

}  // namespace beft::wire

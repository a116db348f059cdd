#include "lib/wire/earlier_layouts.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <utility>

#include "lib/wire/embedded_schemas.hpp"
#include "lib/wire/lcm_schema.hpp"
#include "lib/wire/lcm_walk.hpp"

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

// hypothesis_t before `located` (held by hypotheses_t and hypothesis_changes_t).
const char* const kHypothesisWithoutLocated = R"(package beft;
struct hypothesis_t
{
    string  object_id;
    double  x;
    double  y;
    double  z;
    string  best_category;
    double  confidence;
    int32_t num_categories;
    string  categories[num_categories];
    double  fused[num_categories];
    boolean seen;
    boolean heard;
    string  seen_as;
    string  heard_as;
    boolean verified;
    boolean falsified;
    int64_t first_heard_utime;
    int64_t first_seen_utime;
    int64_t settled_utime;
}
)";

// acoustic_percept_t before `located` (held by acoustic_percepts_t).
const char* const kAcousticPerceptWithoutLocated = R"(package beft;
struct acoustic_percept_t
{
    string  object_id;
    double  occlusion;
    double  est_x;
    double  est_y;
    double  est_z;
    string  acoustic_label;
    string  activity;
    double  level;
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

// A struct that gained members at its end and travels inside messages (an
// element of their arrays): every type holding it changed its fingerprint,
// and each of its instances in such a message gains the members as zero
// bytes. Found by walking the message with the earlier definitions, since the
// instances sit after strings and arrays of any length.
struct NestedChange {
  const char* file;  // today's .lcm file of the struct
  const char* type;  // "beft.hypothesis_t"
  const char* earlier;
  std::size_t added_bytes;
};

const NestedChange kNestedChanges[] = {
    // `located` closes each hypothesis; 0 = false, not known to be located.
    {"hypothesis_t.lcm", "beft.hypothesis_t", kHypothesisWithoutLocated, 1},
    // `located` closes each percept; 0 = false.
    {"acoustic_percept_t.lcm", "beft.acoustic_percept_t", kAcousticPerceptWithoutLocated, 1},
};

struct Upgrade {
  uint64_t earlier = 0, today = 0;
  const LayoutChange* change = nullptr;
};

// A message type that holds a NestedChange's struct, in the earlier layout.
struct NestedUpgrade {
  uint64_t earlier = 0, today = 0;
  std::shared_ptr<const LcmTypeSet> earlier_types;  // today's files, the changed one as it was
  std::string message_type;                          // "beft.hypotheses_t"
  const NestedChange* change = nullptr;
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

const std::vector<NestedUpgrade>& nestedUpgrades() {
  static const std::vector<NestedUpgrade> all = [] {
    std::vector<NestedUpgrade> found;
    LcmTypeSet today;
    for (const EmbeddedSchema& schema : embeddedLcmSchemas()) today.addSchema(schema.file, schema.text);
    today.finalize();
    for (const NestedChange& change : kNestedChanges) {
      auto earlier = std::make_shared<LcmTypeSet>();
      for (const EmbeddedSchema& schema : embeddedLcmSchemas())
        if (schema.file == change.file)
          earlier->addSchema(schema.file + " (earlier)", change.earlier);
        else
          earlier->addSchema(schema.file, schema.text);
      earlier->finalize();
      for (const std::string& name : today.typeNames()) {
        if (name == change.type || earlier->find(name) == nullptr) continue;
        NestedUpgrade upgrade;
        upgrade.today = today.fingerprint(name);
        upgrade.earlier = earlier->fingerprint(name);
        if (upgrade.earlier == upgrade.today) continue;  // does not hold the changed struct
        upgrade.earlier_types = earlier;
        upgrade.message_type = name;
        upgrade.change = &change;
        found.push_back(std::move(upgrade));
      }
    }
    return found;
  }();
  return all;
}

// Where each instance of one struct type ends in a walked message.
class InstanceEnds : public LcmVisitor {
 public:
  InstanceEnds(const LcmReader& reader, std::string type) : reader_(reader), type_(std::move(type)) {}

  void scalar(const LcmMember&, const std::string&, const LcmValue&) override {}
  void bytes(const LcmMember&, const std::string&, const uint8_t*, std::size_t) override {}
  void beginStruct(const LcmMember&, const std::string&, const LcmStruct& type) override {
    open_.push_back(type.fullName() == type_);
  }
  void endStruct() override {
    if (open_.back()) ends.push_back(reader_.position());
    open_.pop_back();
  }
  void beginArray(const LcmMember&, const std::string&, int64_t, bool) override {}
  void endArray() override {}

  std::vector<std::size_t> ends;  // [bytes] after the fingerprint, in order

 private:
  const LcmReader& reader_;
  std::string type_;
  std::vector<bool> open_;
};

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
  for (const NestedUpgrade& upgrade : nestedUpgrades()) {
    if (fingerprint != upgrade.earlier) continue;
    const LcmStruct* type = upgrade.earlier_types->find(upgrade.message_type);
    LcmReader reader(data.data() + kFingerprintBytes, data.size() - kFingerprintBytes);
    InstanceEnds instances(reader, upgrade.change->type);
    try {
      walkLcmStruct(*upgrade.earlier_types, *type, reader, instances);
    } catch (const LcmWalkError&) {
      return false;  // not a message of the earlier layout after all: left for the guard to refuse
    }
    if (reader.remaining() != 0) return false;
    std::vector<uint8_t> upgraded;
    upgraded.reserve(data.size() + instances.ends.size() * upgrade.change->added_bytes);
    std::size_t copied = 0;
    for (const std::size_t end : instances.ends) {
      const std::size_t at = kFingerprintBytes + end;
      upgraded.insert(upgraded.end(), data.begin() + static_cast<std::ptrdiff_t>(copied),
                      data.begin() + static_cast<std::ptrdiff_t>(at));
      upgraded.insert(upgraded.end(), upgrade.change->added_bytes, uint8_t{0});
      copied = at;
    }
    upgraded.insert(upgraded.end(), data.begin() + static_cast<std::ptrdiff_t>(copied), data.end());
    writeFingerprint(upgrade.today, upgraded);
    data = std::move(upgraded);
    return true;
  }
  return false;
}

}  // namespace beft::wire

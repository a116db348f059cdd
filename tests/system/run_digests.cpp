#include "tests/system/run_digests.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <limits>
#include <set>

#include <beft/camera_frame_t.hpp>

#include "lib/camera/frame_decoding.hpp"
#include "lib/compare/data_order.hpp"
#include "lib/common/channels.hpp"
#include "lib/wire/encoded_stamp.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/message_decoder.hpp"
#include "lib/wire/obstacle_map_changes.hpp"
#include "lib/wire/obstacle_map_codec.hpp"

namespace beft::system_test {
namespace {

// Every data message of the run, a refused one too, per channel in the order
// runs are compared (lib/compare/data_order.hpp).
using DataMessages = std::map<std::string, compare::ChannelMessages>;

template <typename Message>
std::vector<uint8_t> encoded(const Message& message) {
  std::vector<uint8_t> bytes(message.getEncodedSize());
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

// A camera frame as its pixels: what the digest pins is the image, not how
// zstd (whose version may change its bytes) packed it.
std::vector<uint8_t> unpackedFrame(const std::vector<uint8_t>& data) {
  beft::camera_frame_t frame{};
  if (!wire::guardedDecode(data.data(), data.size(), frame).ok() || !camera::decodeCameraFrame(frame)) return data;
  return encoded(frame);
}

// An obstacle map as its cells, for the same reason (RLE_ZSTD).
std::vector<uint8_t> unpackedMap(const std::vector<uint8_t>& data) {
  beft::obstacle_map_t map{};
  if (!wire::guardedDecode(data.data(), data.size(), map).ok()) return data;
  try {
    map.data = planners::makeObstacleMap(planners::decodeObstacleMap(map), beft::obstacle_map_t::ENCODING_RAW).data;
  } catch (const planners::ObstacleMapError&) {
    return data;
  }
  map.data_size = static_cast<int32_t>(map.data.size());
  map.encoding = beft::obstacle_map_t::ENCODING_RAW;
  return encoded(map);
}

using DigestVisitor = std::function<void(const std::string& channel, const std::vector<uint8_t>& bytes)>;

// The whole obstacle map of every tick, from the keyframes and the changes:
// as a map of every tick was sent (raw, its tick's time).
void visitWholeMaps(const DataMessages& messages, const DigestVisitor& visit) {
  std::map<int64_t, beft::obstacle_map_t> keyframes;
  std::map<int64_t, beft::obstacle_map_changes_t> changes_of_tick;
  for (const auto& [channel, placed] : messages) {
    for (const auto& [place, entry] : placed) {
      const std::vector<uint8_t>& data = entry.message->data;
      if (channel == channels::kObstacleMap) {
        beft::obstacle_map_t keyframe{};
        if (wire::guardedDecode(data.data(), data.size(), keyframe).ok()) keyframes[keyframe.tick] = keyframe;
      } else if (channel == channels::kObstacleMapChanges) {
        beft::obstacle_map_changes_t changes{};
        if (wire::guardedDecode(data.data(), data.size(), changes).ok()) changes_of_tick[changes.tick] = changes;
      }
    }
  }
  planners::ObstacleMapAssembler assembler;
  for (const auto& [tick, changes] : changes_of_tick) {
    const auto keyframe = keyframes.find(changes.keyframe_tick);
    if (keyframe == keyframes.end()) continue;
    beft::obstacle_map_t whole = keyframe->second;
    try {
      whole.data = assembler.mapOf(keyframe->second, &changes)->cells;
    } catch (const planners::ObstacleMapError&) {
      continue;
    }
    whole.utime = changes.utime;
    whole.tick = changes.tick;
    whole.encoding = beft::obstacle_map_t::ENCODING_RAW;
    whole.data_size = static_cast<int32_t>(whole.data.size());
    visit(channels::kObstacleMap.name, encoded(whole));
  }
}

// Every message as the digest takes it, per channel in order.
void forEachDigestedMessage(const std::vector<LoggedMessage>& log, const DigestVisitor& visit) {
  const DataMessages messages = compare::dataMessagesByChannel(log);
  const bool changes_sent = messages.count(channels::kHypothesisChanges.name) > 0;
  const bool map_changes_sent = messages.count(channels::kObstacleMapChanges.name) > 0;
  for (const auto& [channel, placed] : messages) {
    if (changes_sent && channel == channels::kHypotheses) continue;
    if (map_changes_sent && channel == channels::kObstacleMap) continue;
    const std::string type = channels::typeOfChannel(channel);
    for (const auto& [place, entry] : placed) {
      const std::vector<uint8_t>& data = entry.message->data;
      if (type == lcmTypeName<beft::camera_frame_t>()) visit(channel, unpackedFrame(data));
      else if (type == lcmTypeName<beft::obstacle_map_t>()) visit(channel, unpackedMap(data));
      else visit(channel, data);
    }
  }
  if (map_changes_sent) visitWholeMaps(messages, visit);
  if (changes_sent)
    for (const auto& whole : hypothesesOfEachTick(log)) visit(channels::kHypotheses.name, encoded(whole));
}

constexpr uint64_t kFnvBasis = 1469598103934665603ull, kFnvPrime = 1099511628211ull;

uint64_t fnv1a(uint64_t hash, const std::vector<uint8_t>& bytes) {
  for (const uint8_t byte : bytes) hash = (hash ^ byte) * kFnvPrime;
  return hash;
}

uint32_t fingerprintOf(const std::vector<uint8_t>& bytes) {
  const uint64_t hash = fnv1a(kFnvBasis, bytes);
  return static_cast<uint32_t>(hash ^ (hash >> 32));
}

std::vector<uint32_t> parseFingerprints(const nlohmann::json& text) {
  std::vector<uint32_t> out;
  if (!text.is_string()) return out;
  const std::string hex = text.get<std::string>();
  for (std::size_t at = 0; at + 8 <= hex.size(); at += 8)
    out.push_back(static_cast<uint32_t>(std::stoul(hex.substr(at, 8), nullptr, 16)));
  return out;
}

}  // namespace

RunDigests digestRun(const std::vector<LoggedMessage>& log) {
  RunDigests digests;
  forEachDigestedMessage(log, [&digests](const std::string& channel, const std::vector<uint8_t>& bytes) {
    ChannelDigest& digest = digests.channels[channel];
    ++digest.count;
    digest.hash = fnv1a(digest.hash, bytes);
    digests.fingerprints[channel].push_back(fingerprintOf(bytes));
  });
  return digests;
}

nlohmann::json digestsAsJson(const RunDigests& digests) {
  nlohmann::json out = nlohmann::json::object();
  char hex[17];
  for (const auto& [channel, digest] : digests.channels) {
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(digest.hash));
    out[channel] = {{"count", digest.count}, {"fnv1a64", hex}};
  }
  return out;
}

nlohmann::json fingerprintsAsJson(const RunDigests& digests) {
  nlohmann::json out = nlohmann::json::object();
  char hex[9];
  for (const auto& [channel, fingerprints] : digests.fingerprints) {
    std::string text;
    for (const uint32_t fingerprint : fingerprints) {
      std::snprintf(hex, sizeof hex, "%08x", fingerprint);
      text += hex;
    }
    out[channel] = text;
  }
  return out;
}

namespace {

// The first message of a differing channel that differs from the pinned
// build's: the first whose fingerprint differs, else the first beyond the
// shorter of the two runs.
std::size_t firstDifferingIndex(const std::vector<uint32_t>& actual, const std::vector<uint32_t>& pinned) {
  const auto mismatch = std::mismatch(actual.begin(), actual.end(), pinned.begin(), pinned.end());
  return static_cast<std::size_t>(mismatch.first - actual.begin());
}

struct DifferingMessage {
  std::string channel;
  std::size_t index = 0, count = 0, pinned_count = 0;
  bool fingerprints_pinned = false;
  std::vector<uint8_t> bytes;  // as this run has it; empty: this run has no message there
  int64_t utime = std::numeric_limits<int64_t>::max();
};

std::string describe(const DifferingMessage& message) {
  std::string text = message.channel + " message #" + std::to_string(message.index);
  int64_t tick = 0;
  if (wire::encodedTick(message.bytes.data(), message.bytes.size(), tick))
    text += " (tick " + std::to_string(tick) + ")";
  if (!message.fingerprints_pinned)
    text += " (no fingerprints pinned for the channel: the first message is named)";
  if (message.bytes.empty())
    return text + ": missing (this run has " + std::to_string(message.count) + " messages, the pinned build " +
           std::to_string(message.pinned_count) + ")\n";
  text += message.index >= message.pinned_count ? ": an extra message; it reads:\n" : ": differs; it now reads:\n";
  for (const auto& line : blackboard::MessageDecoder::beftTypes().describeLines(
           message.channel, message.bytes.data(), static_cast<int>(message.bytes.size())))
    text += "    " + line + "\n";
  return text;
}

}  // namespace

std::string digestMismatch(const std::vector<LoggedMessage>& log, const RunDigests& digests,
                           const nlohmann::json& pinned, const nlohmann::json& pinned_fingerprints) {
  const nlohmann::json actual = digestsAsJson(digests);
  std::set<std::string> names;
  for (const auto& [channel, digest] : pinned.items()) names.insert(channel);
  for (const auto& [channel, digest] : actual.items()) names.insert(channel);
  std::map<std::string, DifferingMessage> differing;
  std::string summary;
  for (const std::string& channel : names) {
    const nlohmann::json now = actual.value(channel, nlohmann::json()), then = pinned.value(channel, nlohmann::json());
    if (now == then) continue;
    summary += "  " + channel + ": now " + (now.is_null() ? "absent" : now.dump()) + ", pinned " +
               (then.is_null() ? "absent" : then.dump()) + "\n";
    DifferingMessage& message = differing[channel];
    message.channel = channel;
    message.count = now.is_null() ? 0 : now["count"].get<std::size_t>();
    message.pinned_count = then.is_null() ? 0 : then["count"].get<std::size_t>();
    message.fingerprints_pinned = pinned_fingerprints.contains(channel);
    const auto found = digests.fingerprints.find(channel);
    message.index = firstDifferingIndex(found == digests.fingerprints.end() ? std::vector<uint32_t>() : found->second,
                                        parseFingerprints(pinned_fingerprints.value(channel, nlohmann::json())));
  }
  if (differing.empty()) return "";
  std::map<std::string, std::size_t> seen;
  forEachDigestedMessage(log, [&](const std::string& channel, const std::vector<uint8_t>& bytes) {
    const std::size_t index = seen[channel]++;
    const auto it = differing.find(channel);
    if (it == differing.end() || it->second.index != index) return;
    it->second.bytes = bytes;
    wire::encodedUtime(bytes.data(), bytes.size(), it->second.utime);
  });
  // The earliest differing message: a difference at tick k often causes those after it.
  const auto earliest = std::min_element(differing.begin(), differing.end(), [](const auto& a, const auto& b) {
    return a.second.utime < b.second.utime;
  });
  return "data messages differ from the pinned build's on " + std::to_string(differing.size()) + " channel(s):\n" +
         summary + "earliest differing message: " + describe(earliest->second);
}

}  // namespace beft::system_test

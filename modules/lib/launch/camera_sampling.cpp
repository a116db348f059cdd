#include "lib/launch/camera_sampling.hpp"

#include <stdexcept>

#include <beft/camera_frame_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/wire/encoded_stamp.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::record {

namespace {

// The tick of an encoded camera_frame_t: after its fingerprint and utime.
bool tickOfFrame(const uint8_t* data, std::size_t size, int64_t& tick) {
  if (data == nullptr || size < 8) return false;
  uint64_t fingerprint = 0;
  for (std::size_t i = 0; i < 8; ++i) fingerprint = (fingerprint << 8) | data[i];
  if (fingerprint != static_cast<uint64_t>(beft::camera_frame_t::getHash())) return false;
  return wire::encodedTick(data, size, tick);
}

}  // namespace

bool isCameraChannel(std::string_view channel) {
  const std::string_view base = wire::splitRunChannel(channel).base;
  return base == channels::kCameraColor || base == channels::kCameraDepth || base == channels::kCameraInstance;
}

CameraSampling CameraSampling::parse(const std::string& text) {
  CameraSampling sampling;
  if (text == "all") return sampling;
  if (text == "none") {
    sampling.every_ = 0;
    return sampling;
  }
  const std::string prefix = "every:";
  if (text.compare(0, prefix.size(), prefix) == 0) {
    const std::string number = text.substr(prefix.size());
    std::size_t used = 0;
    long long every = 0;
    try {
      every = std::stoll(number, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == number.size() && !number.empty() && every >= 1) {
      sampling.every_ = every;
      return sampling;
    }
  }
  throw std::invalid_argument("camera frames to record: '" + text + "' (all, none or every:N with N >= 1)");
}

std::string CameraSampling::problemWith(const std::string& text) {
  try {
    parse(text);
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

std::string CameraSampling::text() const {
  if (every_ == 1) return "all";
  if (every_ == 0) return "none";
  return "every:" + std::to_string(every_);
}

bool CameraSampling::keeps(std::string_view channel, const uint8_t* data, std::size_t size) const {
  if (every_ == 1 || !isCameraChannel(channel)) return true;
  if (every_ == 0) return false;
  int64_t tick = 0;
  if (!tickOfFrame(data, size, tick)) return true;
  return tick % every_ == 0;
}

}  // namespace beft::record

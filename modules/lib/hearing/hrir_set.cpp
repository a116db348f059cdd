#include "lib/hearing/hrir_set.hpp"

#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <utility>

namespace beft::hearing {

namespace {

// Longer responses than this are not HRIRs (the KEMAR set has 512 taps):
// a room response or a wrong file, and the renderer's FFTs would grow with it.
constexpr int64_t kMaxTaps = 16384;
constexpr int kMaxDirections = 3600;

double energy(const float* x, int n) {
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += static_cast<double>(x[i]) * x[i];
  return sum;
}

// First sample reaching `fraction` of the response's peak magnitude: its onset.
int onset(const float* x, int n, double fraction = 0.2) {
  float peak = 0;
  for (int i = 0; i < n; ++i) peak = std::max(peak, std::fabs(x[i]));
  for (int i = 0; i < n; ++i)
    if (std::fabs(x[i]) >= fraction * peak) return i;
  return 0;
}

std::string directionText(int direction, int directions) {
  const double azimuth = direction * 360.0 / directions;
  return "a source at " + std::to_string(static_cast<int>(std::lround(azimuth > 180 ? azimuth - 360 : azimuth))) +
         " deg (channels " + std::to_string(2 * direction) + " and " + std::to_string(2 * direction + 1) + ")";
}

// The layout's claim, checked on the data: a source on the left reaches the
// left ear earlier and louder, one on the right the right ear. On the KEMAR
// file, at +90 deg the left ear's onset is at sample 53 and the right's at
// 89 (0.82 ms later), and the left ear gets 16 dB more energy; -90 deg is
// the mirror image (53 / 88, 16.2 dB). Needs a direction at exactly +-90.
void checkEarsAreLeftThenRight(const HrirSet& set, const std::string& path) {
  const int directions = set.directionCount();
  if (directions % 4 != 0) return;
  const int n = set.length();
  struct Side {
    int direction;
    Ear near, far;
    const char* name;
  };
  for (const Side side : {Side{directions / 4, Ear::Left, Ear::Right, "left"},
                          Side{3 * directions / 4, Ear::Right, Ear::Left, "right"}}) {
    const float* near = set.response(side.direction, side.near);
    const float* far = set.response(side.direction, side.far);
    if (energy(near, n) <= energy(far, n) || onset(near, n) > onset(far, n)) {
      throw HrirError("'" + path + "': " + directionText(side.direction, directions) + " does not reach the " +
                      side.name + " ear first and loudest; expected channel 2k = left ear, 2k+1 = right ear for "
                      "k * " + std::to_string(360.0 / directions) + " degrees counter-clockwise from the front");
    }
  }
}

}  // namespace

HrirSet::HrirSet(std::string name, double sample_rate, int length, int directions, std::vector<float> responses,
                 double centre_delay_samples)
    : name_(std::move(name)),
      sample_rate_(sample_rate),
      length_(length),
      directions_(directions),
      responses_(std::move(responses)),
      centre_delay_samples_(centre_delay_samples) {
  if (!(sample_rate_ > 0) || !std::isfinite(sample_rate_)) {
    throw HrirError(name_ + ": sample rate " + std::to_string(sample_rate_) + " Hz is not positive");
  }
  if (length_ < 1 || length_ > kMaxTaps) {
    throw HrirError(name_ + ": " + std::to_string(length_) + " taps per response, expected 1 to " +
                    std::to_string(kMaxTaps));
  }
  if (directions_ < 1 || directions_ > kMaxDirections) {
    throw HrirError(name_ + ": " + std::to_string(directions_) + " directions, expected 1 to " +
                    std::to_string(kMaxDirections));
  }
  if (responses_.size() != static_cast<std::size_t>(2) * directions_ * length_) {
    throw HrirError(name_ + ": " + std::to_string(responses_.size()) + " values for " + std::to_string(directions_) +
                    " directions x 2 ears x " + std::to_string(length_) + " taps");
  }
  for (std::size_t i = 0; i < responses_.size(); ++i) {
    if (!std::isfinite(responses_[i])) {
      const std::size_t channel = i / length_;
      throw HrirError(name_ + ": channel " + std::to_string(channel) + " has a value that is not finite at tap " +
                      std::to_string(i % length_));
    }
  }
  if (!std::isfinite(centre_delay_samples_) || centre_delay_samples_ < 0) {
    throw HrirError(name_ + ": centre delay " + std::to_string(centre_delay_samples_) + " samples is not >= 0");
  }
}

const float* HrirSet::response(int direction, Ear ear) const {
  return responses_.data() + (static_cast<std::size_t>(2) * direction + static_cast<int>(ear)) * length_;
}

void HrirSet::responsesAt(double azimuth_deg, float* left, float* right) const {
  double wrapped = std::fmod(azimuth_deg, 360.0);
  if (wrapped < 0) wrapped += 360.0;
  if (!std::isfinite(wrapped)) wrapped = 0;  // callers check; never index out of range
  const double position = wrapped / directionStepDeg();
  const double below = std::floor(position);
  const float weight = static_cast<float>(position - below);
  const int first = static_cast<int>(below) % directions_;
  const int second = (first + 1) % directions_;
  for (const auto& [ear, out] : {std::pair<Ear, float*>{Ear::Left, left}, std::pair<Ear, float*>{Ear::Right, right}}) {
    const float* a = response(first, ear);
    const float* b = response(second, ear);
    for (int i = 0; i < length_; ++i) out[i] = a[i] + weight * (b[i] - a[i]);
  }
}

HrirSet HrirSet::loadKemar(const std::string& path) {
  SF_INFO info{};
  SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
  if (file == nullptr) {
    std::string why = sf_strerror(nullptr);
    std::error_code error;
    if (!std::filesystem::exists(path, error)) {
      why = "no such file";
      if (path == kKemarPath) why += " (installed by the Debian package " + std::string(kKemarPackage) + ")";
    }
    throw HrirError("cannot read HRIR set '" + path + "': " + why);
  }
  std::unique_ptr<SNDFILE, int (*)(SNDFILE*)> closer(file, sf_close);
  if (info.channels < 2 || info.channels % 2 != 0) {
    throw HrirError("'" + path + "' has " + std::to_string(info.channels) +
                    " channels; an HRIR set has two per direction (left and right ear), e.g. 720 for 1-degree steps");
  }
  if (info.channels / 2 > kMaxDirections) {
    throw HrirError("'" + path + "' has " + std::to_string(info.channels) + " channels, more than " +
                    std::to_string(2 * kMaxDirections) + " for " + std::to_string(kMaxDirections) + " directions");
  }
  if (info.frames < 1 || info.frames > kMaxTaps) {
    throw HrirError("'" + path + "' has " + std::to_string(info.frames) + " samples per channel; an HRIR has 1 to " +
                    std::to_string(kMaxTaps));
  }
  if (info.samplerate <= 0) throw HrirError("'" + path + "' has no valid sample rate");

  const int channels = info.channels;
  const int taps = static_cast<int>(info.frames);
  std::vector<float> interleaved(static_cast<std::size_t>(channels) * taps);
  const sf_count_t read = sf_readf_float(file, interleaved.data(), taps);
  if (read != taps) {
    throw HrirError("'" + path + "': read " + std::to_string(read) + " of " + std::to_string(taps) +
                    " samples per channel (" + sf_strerror(file) + ")");
  }
  const int directions = channels / 2;
  std::vector<float> responses(interleaved.size());
  for (int channel = 0; channel < channels; ++channel)
    for (int tap = 0; tap < taps; ++tap)
      responses[static_cast<std::size_t>(channel) * taps + tap] =
          interleaved[static_cast<std::size_t>(tap) * channels + channel];
  if (energy(responses.data(), static_cast<int>(responses.size())) == 0) {
    throw HrirError("'" + path + "' is silent: every response is zero");
  }

  // Sound from straight ahead reaches both ears when it passes the head
  // centre (plus the few microseconds of the path round to the ears): the
  // mean onset of the two ears at 0 degrees is the set's centre delay.
  const float* front_left = responses.data();
  const float* front_right = responses.data() + taps;
  const double centre_delay = 0.5 * (onset(front_left, taps) + onset(front_right, taps));

  HrirSet set("KEMAR HRIRs from '" + path + "'", info.samplerate, taps, directions, std::move(responses),
              centre_delay);
  checkEarsAreLeftThenRight(set, path);
  return set;
}

HrirSet HrirSet::loadDefault(const Warning& warn, const std::string& kemar_path) {
  try {
    return loadKemar(kemar_path);
  } catch (const HrirError& error) {
    if (warn) {
      std::string message = error.what();
      if (message.find(kKemarPackage) == std::string::npos) {
        message += std::string(" (the KEMAR set is installed by the Debian package ") + kKemarPackage + ")";
      }
      warn(message + "; using the spherical-head model (Brown & Duda 1998) instead, which has no pinna cues");
    }
    return sphericalHead();
  }
}

}  // namespace beft::hearing

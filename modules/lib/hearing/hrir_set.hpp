// Head-related impulse responses for the horizontal plane: for directions
// spaced evenly around the head, what each ear receives from a source there.
// Azimuth in degrees, counter-clockwise seen from above, 0 = the nose, so
// +90 is the listener's left (as alpha in spec/model.md).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace beft::hearing {

class HrirError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Ear { Left = 0, Right = 1 };

class HrirSet {
 public:
  // The KEMAR set of Wierstorf et al. (TU Berlin, AES 2011) as the SoundScape
  // Renderer ships it, and the Debian package that installs it.
  static constexpr const char* kKemarPath = "/usr/share/ssr/impulse_responses/hrirs/hrirs_kemar.wav";
  static constexpr const char* kKemarPackage = "soundscaperenderer-common";

  // Reads a WAV file of 2 D channels for D directions k * 360 / D degrees:
  // channel 2k is the left ear, 2k+1 the right one (the SSR's layout; the
  // KEMAR file has D = 360, 512 taps at 44.1 kHz). Throws HrirError naming
  // the file and what is wrong (missing, not audio, odd channel count, too
  // long, not finite, silent, ears the wrong way round).
  static HrirSet loadKemar(const std::string& path = kKemarPath);

  // The spherical-head model of Brown and Duda (1998) at 1-degree steps:
  // head radius 0.0875 m, ears at +-100 degrees as in the paper, each ear a
  // one-pole/one-zero head-shadow filter and the Woodworth delay. No pinna
  // or shoulder echoes (a horizontal-plane set has no use for them).
  static HrirSet sphericalHead(double sample_rate = 44100);

  // The KEMAR file if it can be read, otherwise the spherical head, after
  // passing a warning that names the file, why it failed, and the package.
  using Warning = std::function<void(const std::string&)>;
  static HrirSet loadDefault(const Warning& warn, const std::string& kemar_path = kKemarPath);

  // responses: direction-major, then ear (left, right), then tap:
  // responses[(2 * direction + ear) * length + tap]. centre_delay_samples: the
  // time, in the responses, at which a wave front passing the head centre
  // (were the head absent) arrives; the renderer takes it off the
  // propagation delay. Throws HrirError if the sizes do not match or a value
  // is not finite.
  HrirSet(std::string name, double sample_rate, int length, int directions, std::vector<float> responses,
          double centre_delay_samples);

  const std::string& name() const { return name_; }
  double sampleRate() const { return sample_rate_; }
  int length() const { return length_; }
  int directionCount() const { return directions_; }
  double directionStepDeg() const { return 360.0 / directions_; }
  double centreDelaySamples() const { return centre_delay_samples_; }

  // The measured response of direction index d (0 <= d < directionCount()).
  const float* response(int direction, Ear ear) const;

  // The responses at any azimuth (wrapped), each length() taps, interpolated
  // linearly between the two nearest measured directions. Plain, not
  // time-aligned, interpolation: at 1-degree steps an ear's delay changes by
  // at most a/c per radian (a ~ 9 cm), about 0.2 samples at 44.1 kHz, so
  // mixing neighbours acts as a fractional delay whose comb-filter notch
  // (where that difference is half a period) lies near 100 kHz, far above
  // Nyquist; nearest-direction lookup would make a turning head's ITD jump in
  // steps.
  void responsesAt(double azimuth_deg, float* left, float* right) const;

 private:
  std::string name_;
  double sample_rate_;
  int length_;
  int directions_;
  std::vector<float> responses_;
  double centre_delay_samples_;
};

}  // namespace beft::hearing

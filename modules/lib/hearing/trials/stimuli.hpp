// Stimuli for trials of the localiser (its statistical tests and
// ./beft bench hearing): noises, the scenario sounds at 44.1 kHz, and ear
// signals made by convolving sources with the KEMAR responses that the
// simulation renders with (a direct convolution, independent of the
// renderer's and the localiser's code).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace beft::hearing::trials {

inline constexpr double kRate = 44100;
inline constexpr int kBlock = 4410;  // 0.1 s

std::vector<float> whiteNoise(int samples, std::mt19937_64& random, float rms = 0.1f);
std::vector<float> pinkNoise(int samples, std::mt19937_64& random, float rms = 0.1f);
// The folder of the scenario sounds (scenarios/sounds of this source tree).
std::string scenarioSoundsDir();
// A scenario sound (DIR/NAME.wav, DIR the folder above by default) resampled
// to 44.1 kHz and scaled to `rms`; throws std::runtime_error if unreadable.
std::vector<float> scenarioSound(const std::string& name, float rms = 0.1f, const std::string& dir = scenarioSoundsDir());
// RMS of samples [first, first + count) of a looped signal.
double loopedRms(const std::vector<float>& signal, long first, int count);

struct PlacedSound {
  const std::vector<float>* signal;  // looped
  double azimuth_deg;                 // head-relative, CCW, whole degrees used
  long offset;                        // sample of the signal heard at the block's first sample
  float gain = 0.5f;                  // 1/r at 2 m
};

// The KEMAR set the simulation renders with: 360 azimuths, 2k left, 2k+1 right.
class KemarEars {
 public:
  KemarEars();  // throws std::runtime_error if the file is missing
  void render(const std::vector<PlacedSound>& sounds, std::vector<float>& left, std::vector<float>& right,
              int samples = kBlock, float noise_rms = 1e-4f, uint64_t noise_seed = 1) const;

 private:
  std::vector<std::vector<float>> left_, right_;
};

}  // namespace beft::hearing::trials

#include "tests/lib/hearing/hearing_test_support.hpp"

#include <cmath>
#include <filesystem>
#include <random>

namespace beft::hearing::test {

bool kemarInstalled() { return std::filesystem::exists(HrirSet::kKemarPath); }

const HrirSet& kemar() {
  static const HrirSet set = HrirSet::loadKemar();
  return set;
}

const BinauralRenderer& kemarRenderer() {
  static const BinauralRenderer renderer(kemar());
  return renderer;
}

SourceSignal whiteNoise(double seconds, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<float> normal(0, 1);
  SourceSignal signal;
  signal.samples.resize(static_cast<std::size_t>(seconds * 44100));
  for (float& sample : signal.samples) sample = normal(random);
  return signal;
}

SourceSignal sine(double frequency_hz, double seconds) {
  SourceSignal signal;
  signal.samples.resize(static_cast<std::size_t>(seconds * 44100));
  for (std::size_t i = 0; i < signal.samples.size(); ++i)
    signal.samples[i] = static_cast<float>(std::sin(2 * M_PI * frequency_hz * i / 44100));
  return signal;
}

BlockRequest staticScene(const SourceSignal& signal, double azimuth_deg, double distance, int64_t first_sample,
                         int num_samples, double occlusion) {
  BlockRequest request;
  request.first_sample = first_sample;
  request.num_samples = num_samples;
  request.noise_rms = 0;
  RenderedSource source;
  source.signal = &signal;
  const double azimuth = azimuth_deg * M_PI / 180;
  source.position = Eigen::Vector3d(distance * std::cos(azimuth), distance * std::sin(azimuth), 0);
  source.occlusion = occlusion;
  request.sources.push_back(source);
  return request;
}

double largestStep(const std::vector<float>& x) {
  double largest = 0;
  for (std::size_t i = 1; i < x.size(); ++i) largest = std::max(largest, std::fabs(double(x[i]) - x[i - 1]));
  return largest;
}

}  // namespace beft::hearing::test

// GCC-PHAT, the ERB bands and the band signatures.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lib/hearing/band_signature.hpp"
#include "lib/hearing/frequency_bands.hpp"
#include "lib/hearing/gcc_phat.hpp"
#include "lib/hearing/trials/stimuli.hpp"

namespace beft::hearing {
namespace {

using trials::kRate;

std::vector<float> delayed(const std::vector<float>& x, int samples) {
  std::vector<float> y(x.size(), 0.0f);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const long from = static_cast<long>(n) - samples;
    if (from >= 0 && from < static_cast<long>(x.size())) y[n] = x[static_cast<std::size_t>(from)];
  }
  return y;
}

TEST(GccPhat, RecoversAKnownDelayWithinASample) {
  std::mt19937_64 random(3);
  const std::vector<float> x = trials::whiteNoise(4410, random);
  for (int delay : {-30, -13, -1, 0, 5, 22, 31}) {
    // right = left delayed: positive, as from a source on the left
    const DelayEstimate found = gccPhatDelay(x, delayed(x, delay), kRate);
    EXPECT_NEAR(found.delay_s * kRate, delay, 1.0) << delay;
    EXPECT_GT(found.peak, 0.5);
  }
}

TEST(GccPhat, RecoversAFractionalDelayWithinASample) {
  // A dense mixture of tones over 80-1500 Hz, delayed by 10.4 samples exactly (analytically).
  std::vector<float> left(4410), right(4410);
  std::mt19937_64 random(4);
  std::uniform_real_distribution<double> phase(0, 2 * M_PI);
  std::vector<std::pair<double, double>> tones;  // [Hz], [rad]
  for (double hz = 80; hz < 1500; hz += 7.3) tones.emplace_back(hz, phase(random));
  for (int n = 0; n < 4410; ++n)
    for (const auto& [hz, start] : tones) {
      left[static_cast<std::size_t>(n)] += static_cast<float>(std::sin(2 * M_PI * hz * n / kRate + start));
      right[static_cast<std::size_t>(n)] += static_cast<float>(std::sin(2 * M_PI * hz * (n - 10.4) / kRate + start));
    }
  EXPECT_NEAR(gccPhatDelay(left, right, kRate).delay_s * kRate, 10.4, 1.0);
}

TEST(GccPhat, SilenceHasNothingToCorrelate) {
  const std::vector<float> zeros(4410, 0.0f);
  const DelayEstimate found = gccPhatDelay(zeros, zeros, kRate);
  EXPECT_EQ(found.peak, 0);
  EXPECT_EQ(found.delay_s, 0);
  EXPECT_EQ(gccPhatDelay({}, {}, kRate).peak, 0);
}

TEST(FrequencyBands, ContiguousOverTheRangeWithAnEdgeAtTheSplit) {
  const FrequencyBands bands(1024, kRate, 80, 16000, 1.0, 1500);
  ASSERT_GT(bands.size(), 20);
  for (int b = 1; b < bands.size(); ++b) {
    EXPECT_EQ(bands[b].first_bin, bands[b - 1].end_bin);
    EXPECT_GT(bands[b].end_bin, bands[b].first_bin);
    EXPECT_GT(bands[b].centre_hz, bands[b - 1].centre_hz);
  }
  EXPECT_NEAR(bands[0].low_hz, 80, bands.binHz());
  EXPECT_NEAR(bands[bands.size() - 1].high_hz, 16000, bands.binHz());
  const int split = bands.firstBandFrom(1500);
  ASSERT_GT(split, 0);
  EXPECT_NEAR(bands[split].low_hz, 1500, bands.binHz());
  EXPECT_THROW(FrequencyBands(1024, kRate, 2000, 1000), std::invalid_argument);
}

TEST(BandSignature, SameSoundAlikeDifferentSoundsApart) {
  const AnalysisLayout layout;
  std::mt19937_64 random(5);
  const auto white = trials::whiteNoise(20000, random), pink = trials::pinkNoise(20000, random);
  const auto white_again = trials::whiteNoise(20000, random);
  const BandSignature w = signatureOfSound(white, kRate, layout), w2 = signatureOfSound(white_again, kRate, layout);
  const BandSignature p = signatureOfSound(pink, kRate, layout);
  EXPECT_GT(signatureSimilarity(w, w2), 0.9);
  EXPECT_LT(signatureSimilarity(w, p), signatureSimilarity(w, w2) - 0.3);
  // Level does not matter, only shape.
  std::vector<float> quiet(white);
  for (float& s : quiet) s *= 0.01f;
  EXPECT_NEAR(signatureSimilarity(w, signatureOfSound(quiet, kRate, layout)), 1.0, 1e-6);
  // A sound at its own lower rate lands in the same bands: the siren's tones.
  const auto siren16k = trials::scenarioSound("siren");
  EXPECT_EQ(signatureOfSound(siren16k, kRate, layout).band_energy.size(), w.band_energy.size());
  EXPECT_EQ(signatureSimilarity(w, BandSignature{}), 0);
  EXPECT_THROW(signatureOfSound({0.0f, NAN}, kRate, layout), std::invalid_argument);
}

}  // namespace
}  // namespace beft::hearing

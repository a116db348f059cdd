// The renderer's parts: reading a looped signal between samples, the sensor
// noise, the occlusion filter.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lib/hearing/binaural_cues.hpp"
#include "lib/hearing/fft_convolver.hpp"
#include "lib/hearing/looped_signal.hpp"
#include "lib/hearing/occlusion_filter.hpp"
#include "lib/hearing/sensor_noise.hpp"

using namespace beft::hearing;

TEST(LoopedSignal, HitsTheSamplesAndWrapsBothWays) {
  const std::vector<float> signal = {0, 1, 4, 9, 16, 25, 36};
  EXPECT_FLOAT_EQ(readLooped(signal, 3, 0), 9);
  EXPECT_FLOAT_EQ(readLooped(signal, 3 + 7 * 1000, 0), 9);
  EXPECT_FLOAT_EQ(readLooped(signal, 3 - 7 * 1000, 0), 9);
  EXPECT_FLOAT_EQ(readLooped(signal, -1, 0), 36);
  // Between samples of a parabola, Catmull-Rom is exact away from the seam.
  EXPECT_NEAR(readLooped(signal, 2, 0.5f), 6.25, 1e-5);
  EXPECT_EQ(readLooped({}, 5, 0.5f), 0.0f);
}

TEST(LoopedSignal, ARunEqualsSampleBySampleReading) {
  std::vector<float> signal(101);
  for (std::size_t i = 0; i < signal.size(); ++i) signal[i] = std::sin(0.37f * i) + 0.1f * (i % 7);
  for (const int64_t first : {int64_t{-250}, int64_t{0}, int64_t{95}, int64_t{123456789}}) {
    std::vector<float> run(333);
    readLoopedRun(signal, first, 0.3f, 0.5f, 333, run.data());
    for (int i = 0; i < 333; ++i) {
      ASSERT_EQ(run[i], 0.5f * readLooped(signal, first + i, 0.3f)) << "first " << first << " sample " << i;
      const int64_t wrapped = ((first + i) % 101 + 101) % 101;
      ASSERT_EQ(readLoopedWrapped(signal, wrapped, 0.3f), readLooped(signal, first + i, 0.3f));
    }
  }
  for (const std::vector<float>& tiny : {std::vector<float>{2}, std::vector<float>{1, -1}}) {
    std::vector<float> run(5);
    readLoopedRun(tiny, -3, 0.25f, 1.0f, 5, run.data());
    for (int i = 0; i < 5; ++i) EXPECT_EQ(run[i], readLooped(tiny, -3 + i, 0.25f));
  }
}

TEST(SensorNoise, IsGaussianOfTheGivenLevelAndAFunctionOfTheSample) {
  const int n = 200000;
  std::vector<float> left(n, 0.0f), right(n, 0.0f);
  addSensorNoise(3, 1000, n, 0.5, left.data(), right.data());
  double sum = 0, sum2 = 0, sum4 = 0, cross = 0;
  for (int i = 0; i < n; ++i) {
    sum += left[i];
    sum2 += double(left[i]) * left[i];
    sum4 += std::pow(double(left[i]), 4);
    cross += double(left[i]) * right[i];
  }
  const double variance = sum2 / n;
  EXPECT_NEAR(sum / n, 0, 0.01);
  EXPECT_NEAR(std::sqrt(variance), 0.5, 0.005);
  EXPECT_NEAR(sum4 / n / (variance * variance), 3.0, 0.1);  // kurtosis of a normal (a uniform's is 1.8)
  EXPECT_NEAR(cross / n, 0, 0.01);
  // A piece generated alone is the same piece.
  std::vector<float> piece_left(100, 0.0f), piece_right(100, 0.0f);
  addSensorNoise(3, 1000 + 5000, 100, 0.5, piece_left.data(), piece_right.data());
  for (int i = 0; i < 100; ++i) ASSERT_EQ(piece_left[i], left[5000 + i]);
}

TEST(OcclusionFilter, GainAndCutoffFollowTheOcclusion) {
  EXPECT_DOUBLE_EQ(occlusionGain(0), 1.0);
  EXPECT_DOUBLE_EQ(occlusionGain(1), 0.4);
  EXPECT_NEAR(occlusionCutoffHz(0), 20000, 1e-9);
  EXPECT_NEAR(occlusionCutoffHz(1), 1000, 1e-9);
  EXPECT_NEAR(occlusionCutoffHz(0.5), std::sqrt(20000.0 * 1000.0), 1e-6);
  // The filter: DC gain as above, -6 dB at the cut-off, little beyond twice it.
  const std::vector<float> filter = occlusionFilter(1.0, 44100);
  ASSERT_EQ(filter.size(), 127u);
  double dc = 0;
  for (float tap : filter) dc += tap;
  EXPECT_NEAR(dc, 0.4, 1e-6);
  const auto gainAt = [&](double hz) {
    std::complex<double> sum = 0;
    for (std::size_t n = 0; n < filter.size(); ++n) sum += double(filter[n]) * std::polar(1.0, -2 * M_PI * hz / 44100 * n);
    return std::abs(sum) / dc;
  };
  EXPECT_NEAR(gainAt(1000), 0.5, 0.05);
  EXPECT_LT(gainAt(2500), 0.01);
  EXPECT_NEAR(gainAt(200), 1.0, 0.01);
}

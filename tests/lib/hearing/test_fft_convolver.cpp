// FFT convolution against the direct sum, plan sharing across threads.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>

#include "lib/hearing/fft_convolver.hpp"

using namespace beft::hearing;

namespace {
std::vector<float> randomSignal(int n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> uniform(-1, 1);
  std::vector<float> x(n);
  for (float& v : x) v = uniform(random);
  return x;
}

std::vector<double> directConvolution(const std::vector<float>& x, const std::vector<float>& h) {
  std::vector<double> y(x.size() + h.size() - 1, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t k = 0; k < h.size(); ++k) y[i + k] += double(x[i]) * h[k];
  return y;
}
}  // namespace

TEST(FastFftSize, OnlyFactorsTwoThreeFive) {
  EXPECT_EQ(fastFftSize(1), 1);
  EXPECT_EQ(fastFftSize(7), 8);
  EXPECT_EQ(fastFftSize(4984), 5000);
  EXPECT_EQ(fastFftSize(5047), 5120);
  EXPECT_EQ(fastFftSize(4096), 4096);
}

TEST(RealFft, InverseUndoesForward) {
  const RealFft fft(5000);
  const std::vector<float> x = randomSignal(4321, 1);
  Samples scratch, out;
  Spectrum spectrum;
  fft.forward(x.data(), static_cast<int>(x.size()), scratch, spectrum);
  fft.inverse(spectrum, out);
  for (int i = 0; i < 5000; ++i) ASSERT_NEAR(out[i], i < 4321 ? x[i] : 0.0f, 1e-5) << "sample " << i;
}

TEST(RealFft, RefusesMoreSamplesThanItsSize) {
  const RealFft fft(64);
  const std::vector<float> x(65, 1.0f);
  Samples scratch;
  Spectrum spectrum;
  EXPECT_THROW(fft.forward(x.data(), 65, scratch, spectrum), std::invalid_argument);
  EXPECT_THROW(RealFft(0), std::invalid_argument);
}

TEST(Convolve, EqualsTheDirectSum) {
  const std::vector<float> x = randomSignal(3000, 2), h = randomSignal(512, 3);
  const std::vector<float> fast = convolve(x, h);
  const std::vector<double> direct = directConvolution(x, h);
  ASSERT_EQ(fast.size(), direct.size());
  for (std::size_t i = 0; i < fast.size(); ++i) ASSERT_NEAR(fast[i], direct[i], 2e-4) << "sample " << i;
  EXPECT_TRUE(convolve({}, h).empty());
}

TEST(Convolve, ThreadsPlanningAtOnceGetTheSameResult) {
  // FFTW's planner is not thread-safe: sizes first seen by several threads
  // at once must still be planned once and give the same numbers.
  const std::vector<float> x = randomSignal(1000, 4), h = randomSignal(100, 5);
  std::vector<std::vector<float>> results(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int extra = 0; extra < 20; ++extra) {
        std::vector<float> longer = x;
        longer.resize(x.size() + 37 * extra, 0.0f);  // a new FFT size each round
        const std::vector<float> y = convolve(longer, h);
        if (extra == 0) results[t] = y;
      }
    });
  for (auto& thread : threads) thread.join();
  for (int t = 1; t < 4; ++t) EXPECT_EQ(results[t], results[0]);
}

// Peaks, front-back ambiguity and its resolution by a head turn.
#include <gtest/gtest.h>

#include <cmath>

#include "lib/hearing/azimuth_posterior.hpp"

namespace beft::hearing {
namespace {

// Gaussian bumps (sigma in degrees) at the given azimuths with the given heights.
AzimuthPosterior bumps(const std::vector<std::pair<double, double>>& at_height, double sigma = 5) {
  std::array<double, AzimuthPosterior::kBins> values{};
  for (int a = 0; a < AzimuthPosterior::kBins; ++a) {
    values[static_cast<std::size_t>(a)] = 1e-4;
    for (const auto& [azimuth, height] : at_height) {
      const double d = angularDistance(a, azimuth);
      values[static_cast<std::size_t>(a)] += height * std::exp(-d * d / (2 * sigma * sigma));
    }
  }
  return AzimuthPosterior(values);
}

TEST(AzimuthPosterior, AnglesWrapAndMirror) {
  EXPECT_DOUBLE_EQ(wrapDegrees(-10), 350);
  EXPECT_DOUBLE_EQ(wrapDegrees(725), 5);
  EXPECT_DOUBLE_EQ(angularDistance(350, 10), 20);
  EXPECT_DOUBLE_EQ(frontBackMirror(30), 150);
  EXPECT_DOUBLE_EQ(frontBackMirror(300), 240);
  EXPECT_DOUBLE_EQ(frontBackMirror(90), 90);
}

TEST(AzimuthPosterior, PeaksAreSeparatedLocalMaximaHeaviestFirst) {
  const AzimuthPosterior p = bumps({{40, 1.0}, {50, 0.5}, {200.3, 0.6}, {358, 0.05}});
  const auto peaks = p.peaks(20, 0.1);
  ASSERT_EQ(peaks.size(), 2u);  // 50 lies within 20 degrees of 40; 358 is too light
  EXPECT_NEAR(peaks[0].azimuth_deg, 41, 2);
  EXPECT_NEAR(peaks[1].azimuth_deg, 200.3, 0.5);
  EXPECT_GT(peaks[0].weight, peaks[1].weight);
  EXPECT_TRUE(AzimuthPosterior().peaks().empty());
  EXPECT_TRUE(AzimuthPosterior().isFlat());
  EXPECT_THROW(AzimuthPosterior(std::array<double, 360>{{-1}}), std::invalid_argument);
}

TEST(AzimuthPosterior, BesideTheHeadThereIsNoAmbiguity) {
  EXPECT_FALSE(isFrontBackAmbiguous(bumps({{88, 1.0}})));
  EXPECT_FALSE(isFrontBackAmbiguous(bumps({{30, 1.0}})));
  EXPECT_FALSE(isFrontBackAmbiguous(AzimuthPosterior()));
}

TEST(AzimuthPosterior, TurnedFrameMovesDirectionsTheOtherWay) {
  const AzimuthPosterior p = bumps({{100, 1.0}});
  EXPECT_NEAR(p.inTurnedFrame(30).mostLikely(), 70, 0.5);
  EXPECT_NEAR(p.inTurnedFrame(-120).mostLikely(), 220, 0.5);
}

}  // namespace
}  // namespace beft::hearing

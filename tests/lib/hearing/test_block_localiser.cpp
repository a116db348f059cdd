// The block localiser on synthetic ear signals: pure interaural delays and
// level differences, silence, two sources, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lib/hearing/block_localiser.hpp"
#include "lib/hearing/trials/stimuli.hpp"

namespace beft::hearing {
namespace {

using trials::kBlock;
using trials::kRate;

const BlockLocaliser& localiser() {
  static const BlockLocaliser instance(InterauralTemplates::fromSofa());
  return instance;
}

// Random-phase tones spread over [low_hz, high_hz], the right ear `itd_s`
// later than the left (analytically, so any fraction of a sample) and
// `ild_db` quieter.
struct Tones {
  std::vector<double> hz, phase;
};
Tones randomTones(double low_hz, double high_hz, int count, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> frequency(low_hz, high_hz), phase(0, 2 * M_PI);
  Tones t;
  for (int i = 0; i < count; ++i) t.hz.push_back(frequency(random)), t.phase.push_back(phase(random));
  return t;
}
void addTones(const Tones& tones, double itd_s, double ild_db, float amplitude, std::vector<float>& left,
              std::vector<float>& right) {
  left.resize(kBlock, 0.0f);
  right.resize(kBlock, 0.0f);
  const double right_gain = std::pow(10.0, -ild_db / 20);
  for (int n = 0; n < kBlock; ++n)
    for (std::size_t i = 0; i < tones.hz.size(); ++i) {
      const double w = 2 * M_PI * tones.hz[i];
      left[static_cast<std::size_t>(n)] += amplitude * static_cast<float>(std::sin(w * n / kRate + tones.phase[i]));
      right[static_cast<std::size_t>(n)] +=
          amplitude * static_cast<float>(right_gain * std::sin(w * (n / kRate - itd_s) + tones.phase[i]));
    }
}

double foldedError(double estimate, double truth) {
  return std::min(angularDistance(estimate, truth), angularDistance(estimate, frontBackMirror(truth)));
}

TEST(BlockLocaliser, SilenceGivesNoPeaksAndAFlatPosterior) {
  const std::vector<float> zeros(kBlock, 0.0f);
  const BlockLocalisation silent = localiser().localise(zeros, zeros);
  EXPECT_TRUE(silent.silent());
  EXPECT_TRUE(silent.peaks.empty());
  EXPECT_TRUE(silent.posterior.isFlat());
  // The microphones' own noise (-80 dBFS) is silence too, not a source.
  std::mt19937_64 random(2);
  const auto noise_left = trials::whiteNoise(kBlock, random, 1e-4f), noise_right = trials::whiteNoise(kBlock, random, 1e-4f);
  const BlockLocalisation hiss = localiser().localise(noise_left, noise_right);
  EXPECT_TRUE(hiss.peaks.empty());
  EXPECT_TRUE(hiss.posterior.isFlat());
  EXPECT_TRUE(localiser().localise({}, {}).peaks.empty());
}

// A head's interaural delay grows towards low frequencies (about 1.5 times
// at 200 Hz, Kuhn 1977), so a pure delay, the same at all frequencies, fits
// the templates' phases only roughly: the tolerances below allow for that.
TEST(BlockLocaliser, APureInterauralDelayPointsToItsAzimuth) {
  const InterauralTemplates& templates = localiser().templates();
  const Tones tones = randomTones(100, 1400, 60, 11);
  for (int azimuth : {0, 20, 45, 300, 330}) {
    std::vector<float> left, right;
    addTones(tones, templates.itd(azimuth), 0, 0.02f, left, right);
    const BlockLocalisation found = localiser().localise(left, right);
    ASSERT_FALSE(found.peaks.empty()) << azimuth;
    EXPECT_LT(foldedError(found.peaks[0].azimuth_deg, azimuth), 8) << azimuth << ": " << found.peaks[0].azimuth_deg;
    EXPECT_GT(found.peaks[0].weight, 0.5) << azimuth;
  }
}

TEST(BlockLocaliser, BlocksPooledAcrossAHeadTurnPutTheSourceOnItsSide) {
  // Interaural delays alone are the same at a and 180 - a; between the two
  // blocks the head turns CCW, so the source moves by -turn while its mirror
  // image moves by +turn, and only the true side agrees in both.
  const InterauralTemplates& templates = localiser().templates();
  const Tones tones = randomTones(100, 1400, 60, 21);
  const int turn = static_cast<int>(kDefaultResolvingTurnDeg);
  for (int now : {30, 150, 200, 330}) {
    std::vector<float> left_before, right_before, left_after, right_after;
    addTones(tones, templates.itd(now + turn), 0, 0.02f, left_before, right_before);
    addTones(tones, templates.itd(now), 0, 0.02f, left_after, right_after);
    const BlockLocalisation one = localiser().localise(left_after, right_after);
    ASSERT_FALSE(one.peaks.empty()) << now;
    EXPECT_TRUE(isFrontBackAmbiguous(one.posterior)) << now;
    const BlockLocalisation pooled = localiser().localise(
        {EarBlock{left_before, right_before, static_cast<double>(turn)}, EarBlock{left_after, right_after, 0.0}});
    ASSERT_FALSE(pooled.peaks.empty()) << now;
    EXPECT_LT(angularDistance(pooled.peaks[0].azimuth_deg, now), 5) << now << ": " << pooled.peaks[0].azimuth_deg;
    // Additive pooling: the true direction holds both blocks' votes, each mirror image one block's.
    EXPECT_GT(pooled.posterior.massNear(now, 10), 1.5 * pooled.posterior.massNear(frontBackMirror(now), 10)) << now;
    EXPECT_EQ(pooled.voting_frames, 2 * one.voting_frames);
  }
}

// Tones from one direction during [first, end) of a block, added to it.
void addBurst(const Tones& tones, double itd_s, float amplitude, int first, int end, std::vector<float>& left,
              std::vector<float>& right) {
  std::vector<float> burst_left, burst_right;
  addTones(tones, itd_s, 0, amplitude, burst_left, burst_right);
  left.resize(kBlock, 0.0f);
  right.resize(kBlock, 0.0f);
  for (int n = first; n < end; ++n) {
    left[static_cast<std::size_t>(n)] += burst_left[static_cast<std::size_t>(n)];
    right[static_cast<std::size_t>(n)] += burst_right[static_cast<std::size_t>(n)];
  }
}

TEST(BlockLocaliser, OnsetWeightingHearsTheDirectSoundRatherThanItsLongerEcho) {
  // A burst from 40 deg, then its echo from 300 deg 25 ms later, louder and
  // lasting to the block's end (a reflecting wall near a listener in a
  // reverberant room): most of the block's energy comes from the echo. The
  // defaults follow the energy; onset weighting (the reverberant profile)
  // hears where the sound started.
  const BlockLocaliser reverberant(localiser().templates(), LocaliserConfig::reverberant());
  const InterauralTemplates& templates = localiser().templates();
  const Tones tones = randomTones(150, 1400, 60, 31);
  std::vector<float> left, right;
  addBurst(tones, templates.itd(40), 0.02f, 1500, 2800, left, right);
  addBurst(tones, templates.itd(300), 0.04f, 2600, kBlock, left, right);
  const BlockLocalisation plain = localiser().localise(left, right);
  const BlockLocalisation onsets = reverberant.localise(left, right);
  ASSERT_FALSE(plain.peaks.empty());
  ASSERT_FALSE(onsets.peaks.empty());
  EXPECT_LT(foldedError(plain.peaks[0].azimuth_deg, 300), 10) << plain.peaks[0].azimuth_deg;
  EXPECT_LT(foldedError(onsets.peaks[0].azimuth_deg, 40), 10) << onsets.peaks[0].azimuth_deg;
}

TEST(BlockLocaliser, ALevelDifferenceAlonePointsToTheLouderSide) {
  // Above the highest frequency whose phase is compared (6 kHz): level cues only.
  const Tones high = randomTones(7000, 12000, 80, 12);
  for (double ild : {12.0, -12.0}) {
    std::vector<float> left, right;
    addTones(high, 0, ild, 0.01f, left, right);
    const double azimuth = localiser().localise(left, right).posterior.mostLikely();
    if (ild > 0)
      EXPECT_TRUE(azimuth > 10 && azimuth < 170) << azimuth;
    else
      EXPECT_TRUE(azimuth > 190 && azimuth < 350) << azimuth;
  }
}

TEST(BlockLocaliser, TwoSourcesInDifferentBandsGiveTwoPeaksWithTheirOwnSignatures) {
  const InterauralTemplates& templates = localiser().templates();
  const Tones low = randomTones(100, 500, 30, 21), high = randomTones(700, 1400, 30, 22);
  std::vector<float> left, right;
  addTones(low, templates.itd(40), 0, 0.02f, left, right);     // left front
  addTones(high, templates.itd(300), 0, 0.02f, left, right);   // right front
  const BlockLocalisation found = localiser().localise(left, right);
  ASSERT_GE(found.peaks.size(), 2u);
  const LocalisedPeak* at_left = nullptr;
  const LocalisedPeak* at_right = nullptr;
  for (std::size_t i = 0; i < 2; ++i) {
    const LocalisedPeak& p = found.peaks[i];
    if (foldedError(p.azimuth_deg, 40) < 12) at_left = &p;
    if (foldedError(p.azimuth_deg, 300) < 12) at_right = &p;
  }
  ASSERT_NE(at_left, nullptr);
  ASSERT_NE(at_right, nullptr);
  // Each peak's signature is its own sound's, not the other's.
  std::vector<float> low_alone, high_alone, unused;
  addTones(low, 0, 0, 0.02f, low_alone, unused);
  addTones(high, 0, 0, 0.02f, high_alone, unused);
  const AnalysisLayout& layout = templates.layout();
  const BandSignature low_signature = signatureOfSound(low_alone, kRate, layout);
  const BandSignature high_signature = signatureOfSound(high_alone, kRate, layout);
  EXPECT_GT(signatureSimilarity(at_left->signature, low_signature),
            signatureSimilarity(at_left->signature, high_signature));
  EXPECT_GT(signatureSimilarity(at_right->signature, high_signature),
            signatureSimilarity(at_right->signature, low_signature));
}

TEST(BlockLocaliser, BadInputIsRefusedClearly) {
  std::vector<float> left(kBlock, 0.1f), right(kBlock - 1, 0.1f);
  EXPECT_THROW(localiser().localise(left, right), std::invalid_argument);
  right.push_back(NAN);
  EXPECT_THROW(localiser().localise(left, right), std::invalid_argument);
  LocaliserConfig bad;
  bad.silence_rms = 0;
  EXPECT_THROW(BlockLocaliser(localiser().templates(), bad), std::invalid_argument);
}

TEST(BlockLocaliser, AShortBlockIsPaddedToAFrame) {
  const Tones tones = randomTones(100, 1400, 60, 13);
  std::vector<float> left, right;
  addTones(tones, localiser().templates().itd(30), 0, 0.02f, left, right);
  left.resize(600);
  right.resize(600);
  const BlockLocalisation found = localiser().localise(left, right);
  EXPECT_EQ(found.voting_frames, 1);
  ASSERT_FALSE(found.peaks.empty());
  EXPECT_LT(foldedError(found.peaks[0].azimuth_deg, 30), 10);
}

}  // namespace
}  // namespace beft::hearing

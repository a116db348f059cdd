// The binaural renderer: the cues a listener needs (ITD, ILD) where the
// head's geometry puts them, distance and occlusion, no clicks from a
// turning head, and blocks that are the same however they are cut.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "lib/hearing/binaural_cues.hpp"
#include "lib/hearing/binaural_renderer.hpp"
#include "tests/lib/hearing/hearing_test_support.hpp"

using namespace beft::hearing;
using namespace beft::hearing::test;

#define REQUIRE_KEMAR()                                                                                \
  if (!kemarInstalled())                                                                               \
  GTEST_SKIP() << HrirSet::kKemarPath << " is missing (Debian package " << HrirSet::kKemarPackage << ")"

namespace {

constexpr double kRate = 44100;

const SourceSignal& noise() {
  static const SourceSignal signal = whiteNoise(2.0, 7);
  return signal;
}

struct Cues {
  double itd_ms, ild_high_db, ild_db;
};

Cues cuesAt(const BinauralRenderer& renderer, double azimuth_deg) {
  const StereoBlock block = renderer.render(staticScene(noise(), azimuth_deg, 2.0, 44100, 8820));
  return {interauralTimeDifferenceMs(block.left, block.right, kRate),
          interauralLevelDifferenceDb(block.left, block.right, kRate, 4000),
          interauralLevelDifferenceDb(block.left, block.right, kRate)};
}

double levelDb(const StereoBlock& block) {
  return 10 * std::log10(rms(block.left) * rms(block.left) + rms(block.right) * rms(block.right));
}

}  // namespace

TEST(RendererCues, ASourceOnTheLeftReachesTheLeftEarFirstAndLouder) {
  REQUIRE_KEMAR();
  // The dummy head is not quite symmetric: the KEMAR set gives 0.730 ms at
  // +90 deg and 0.752 ms at -90 deg (its largest ITD, 0.78 ms, is near
  // +-100 deg). Each side within 0.65 to 0.78 ms, their mean within 0.65
  // to 0.75 ms.
  const Cues left = cuesAt(kemarRenderer(), 90);
  EXPECT_GT(left.itd_ms, 0.65);
  EXPECT_LT(left.itd_ms, 0.78);
  EXPECT_GT(left.ild_high_db, 10);
  const Cues right = cuesAt(kemarRenderer(), -90);
  EXPECT_LT(right.itd_ms, -0.65);
  EXPECT_GT(right.itd_ms, -0.78);
  EXPECT_LT(right.ild_high_db, -10);
  const double mean_itd = 0.5 * (left.itd_ms - right.itd_ms);
  EXPECT_GT(mean_itd, 0.65);
  EXPECT_LT(mean_itd, 0.75);
}

TEST(RendererCues, ASourceAheadGivesNoDifference) {
  REQUIRE_KEMAR();
  const Cues ahead = cuesAt(kemarRenderer(), 0);
  EXPECT_NEAR(ahead.itd_ms, 0, 0.03);
  EXPECT_NEAR(ahead.ild_db, 0, 1.0);
}

TEST(RendererCues, TheHeadsYawTurnsTheScene) {
  REQUIRE_KEMAR();
  // A source straight along +y with the nose towards +y is ahead.
  BlockRequest request = staticScene(noise(), 90, 2.0, 0, 8820);
  request.previous.yaw_deg = request.current.yaw_deg = 90;
  const StereoBlock block = kemarRenderer().render(request);
  EXPECT_NEAR(interauralTimeDifferenceMs(block.left, block.right, kRate), 0, 0.03);
  EXPECT_DOUBLE_EQ(BinauralRenderer::headAzimuthDeg(request.current, request.sources[0].position), 0);
}

TEST(RendererCues, TheSphericalHeadFallbackGivesPlausibleCues) {
  const BinauralRenderer renderer(HrirSet::sphericalHead(kRate));
  const Cues right = cuesAt(renderer, -90);
  EXPECT_LT(right.itd_ms, -0.5);
  EXPECT_GT(right.itd_ms, -0.8);
  EXPECT_LT(right.ild_db, -3);  // the right ear louder
  EXPECT_LT(right.ild_high_db, -10);
  const Cues ahead = cuesAt(renderer, 0);
  EXPECT_NEAR(ahead.itd_ms, 0, 0.03);
  EXPECT_NEAR(ahead.ild_db, 0, 0.5);
}

TEST(RendererPhysics, TwiceTheDistanceIsSixDecibelsQuieter) {
  REQUIRE_KEMAR();
  const double near = levelDb(kemarRenderer().render(staticScene(noise(), 30, 2.0, 0, 8820)));
  const double far = levelDb(kemarRenderer().render(staticScene(noise(), 30, 4.0, 0, 8820)));
  EXPECT_NEAR(near - far, 6.02, 0.3);
  // Closer than 0.3 m counts as 0.3 m: no level without bound.
  const double closest = levelDb(kemarRenderer().render(staticScene(noise(), 30, 0.3, 0, 8820)));
  const double touching = levelDb(kemarRenderer().render(staticScene(noise(), 30, 0.01, 0, 8820)));
  EXPECT_NEAR(touching, closest, 0.05);
  EXPECT_NEAR(closest - near, 20 * std::log10(2.0 / 0.3), 0.3);
}

TEST(RendererPhysics, SoundArrivesAfterTheDistanceOverTheSpeedOfSound) {
  REQUIRE_KEMAR();
  // One click in 1 s of silence, from ahead at 10 m: heard 29.2 ms in.
  SourceSignal click;
  click.samples.assign(44100, 0.0f);
  click.samples[0] = 1;
  const StereoBlock block = kemarRenderer().render(staticScene(click, 0, 10.0, 0, 4410));
  const auto onset = [](const std::vector<float>& x) {
    float peak = 0;
    for (float v : x) peak = std::max(peak, std::fabs(v));
    for (std::size_t i = 0; i < x.size(); ++i)
      if (std::fabs(x[i]) >= 0.2f * peak) return static_cast<double>(i);
    return -1.0;
  };
  const double expected = 10.0 / 343 * kRate;  // 1285.7 samples
  EXPECT_NEAR(onset(block.left), expected, 3);
  EXPECT_NEAR(onset(block.right), expected, 3);
}

TEST(RendererPhysics, AnOccludedSourceIsQuieterAndDuller) {
  REQUIRE_KEMAR();
  const StereoBlock open = kemarRenderer().render(staticScene(noise(), 45, 3.0, 0, 8820, 0.0));
  const StereoBlock half = kemarRenderer().render(staticScene(noise(), 45, 3.0, 0, 8820, 0.5));
  const StereoBlock blocked = kemarRenderer().render(staticScene(noise(), 45, 3.0, 0, 8820, 1.0));
  EXPECT_LT(levelDb(half), levelDb(open) - 3);
  EXPECT_LT(levelDb(blocked), levelDb(half) - 3);
  const double centroid_open = spectralCentroidHz(open.left, kRate);
  const double centroid_half = spectralCentroidHz(half.left, kRate);
  const double centroid_blocked = spectralCentroidHz(blocked.left, kRate);
  std::printf("spectral centroid, left ear: open %.0f Hz, O_a = 0.5 %.0f Hz, O_a = 1 %.0f Hz\n", centroid_open,
              centroid_half, centroid_blocked);
  EXPECT_LT(centroid_half, 0.85 * centroid_open);
  EXPECT_LT(centroid_blocked, 0.5 * centroid_half);
  EXPECT_LT(centroid_blocked, 1500);
}

TEST(RendererBlocks, BlockByBlockEqualsOneLongRendering) {
  REQUIRE_KEMAR();
  // Three sources, one behind a wall, heard from tick 3 on; the signals
  // loop (0.3 s of noise) and start before the span.
  const SourceSignal a = whiteNoise(0.3, 11), b = whiteNoise(0.25, 12);
  const SourceSignal c = sine(440, 0.5);
  BlockRequest whole = staticScene(a, 60, 2.5, 3 * 4410, 5 * 4410);
  whole.sources.push_back(staticScene(b, -120, 1.2, 0, 0).sources[0]);
  whole.sources.push_back(staticScene(c, 170, 6.0, 0, 0, 0.7).sources[0]);
  whole.sources[1].level = 0.5;
  whole.previous.centre = whole.current.centre = Eigen::Vector3d(0.4, -0.2, 1.2);
  whole.previous.yaw_deg = whole.current.yaw_deg = 25;
  whole.noise_rms = 1e-3;
  whole.noise_seed = 99;
  const StereoBlock long_rendering = kemarRenderer().render(whole);

  double largest_difference = 0;
  for (int k = 0; k < 5; ++k) {
    BlockRequest block = whole;
    block.first_sample = whole.first_sample + k * 4410;
    block.num_samples = 4410;
    const StereoBlock part = kemarRenderer().render(block);
    for (int i = 0; i < 4410; ++i) {
      largest_difference = std::max(largest_difference, std::fabs(double(part.left[i]) - long_rendering.left[k * 4410 + i]));
      largest_difference = std::max(largest_difference, std::fabs(double(part.right[i]) - long_rendering.right[k * 4410 + i]));
    }
  }
  EXPECT_LT(largest_difference, 1e-5);
  EXPECT_GT(rms(long_rendering.left), 0.01);  // not silence compared with silence
}

TEST(RendererBlocks, SameRequestSameOutputAndTheSeedChangesOnlyTheNoise) {
  REQUIRE_KEMAR();
  BlockRequest request = staticScene(noise(), 20, 3.0, 12345, 4410);
  request.noise_rms = 0.01;
  request.noise_seed = 1;
  const StereoBlock first = kemarRenderer().render(request);
  const StereoBlock again = kemarRenderer().render(request);
  EXPECT_EQ(first.left, again.left);
  EXPECT_EQ(first.right, again.right);

  request.noise_seed = 2;
  const StereoBlock other_seed = kemarRenderer().render(request);
  request.noise_rms = 0;
  const StereoBlock quiet = kemarRenderer().render(request);
  std::vector<float> noise_1(4410), noise_2(4410), left_right(4410);
  for (int i = 0; i < 4410; ++i) {
    noise_1[i] = first.left[i] - quiet.left[i];
    noise_2[i] = other_seed.left[i] - quiet.left[i];
    left_right[i] = first.right[i] - quiet.right[i];
  }
  EXPECT_NEAR(rms(noise_1), 0.01, 0.001);
  EXPECT_NEAR(rms(noise_2), 0.01, 0.001);
  // Independent noise: seeds differ, and so do the ears.
  double same_seed_product = 0, other_seed_product = 0, ears_product = 0;
  for (int i = 0; i < 4410; ++i) {
    other_seed_product += double(noise_1[i]) * noise_2[i];
    ears_product += double(noise_1[i]) * left_right[i];
    same_seed_product += double(noise_1[i]) * noise_1[i];
  }
  EXPECT_LT(std::fabs(other_seed_product), 0.1 * same_seed_product);
  EXPECT_LT(std::fabs(ears_product), 0.1 * same_seed_product);
}

TEST(RendererBlocks, ATurningHeadMakesNoClick) {
  REQUIRE_KEMAR();
  // A 300 Hz tone from 40 deg; the head turns at 180 deg/s for 0.5 s
  // (18 deg per block), then the same blocks with the head held at each
  // block's end pose: the turning rendering may not step further from one
  // sample to the next than the static ones do.
  const SourceSignal tone = sine(300, 1.0);
  std::vector<float> turning_left, turning_right;
  double static_step = 0;
  for (int k = 0; k < 5; ++k) {
    BlockRequest request = staticScene(tone, 40, 2.0, k * 4410, 4410);
    request.previous.yaw_deg = 18.0 * k;
    request.current.yaw_deg = 18.0 * (k + 1);
    const StereoBlock block = kemarRenderer().render(request);
    turning_left.insert(turning_left.end(), block.left.begin(), block.left.end());
    turning_right.insert(turning_right.end(), block.right.begin(), block.right.end());
    for (double yaw : {request.previous.yaw_deg, request.current.yaw_deg}) {
      BlockRequest held = request;
      held.previous.yaw_deg = held.current.yaw_deg = yaw;
      const StereoBlock still = kemarRenderer().render(held);
      static_step = std::max({static_step, largestStep(still.left), largestStep(still.right)});
    }
  }
  EXPECT_GT(static_step, 0.001);
  EXPECT_LT(largestStep(turning_left), 1.1 * static_step);
  EXPECT_LT(largestStep(turning_right), 1.1 * static_step);
  // Without the cross-fade, switching HRIRs at a block boundary would jump:
  // the tone's phase at the ears moves by 0.13 ms over 18 deg.
  BlockRequest before = staticScene(tone, 40, 2.0, 4410, 4410), after = before;
  before.previous.yaw_deg = before.current.yaw_deg = 0;
  after.previous.yaw_deg = after.current.yaw_deg = 90;
  const float jump = std::fabs(kemarRenderer().render(after).left[0] - kemarRenderer().render(before).left[0]);
  EXPECT_GT(jump, 3 * static_step);
}

TEST(RendererBlocks, AMovingHeadMovesTheDelaySmoothly) {
  REQUIRE_KEMAR();
  // Walking towards the source at 1 m/s: the delay shortens smoothly
  // (Doppler), with no step at the block boundary.
  const SourceSignal tone = sine(200, 1.0);
  std::vector<float> left;
  for (int k = 0; k < 3; ++k) {
    BlockRequest request = staticScene(tone, 0, 5.0, k * 4410, 4410);
    request.previous.centre = Eigen::Vector3d(0.1 * k, 0, 0);
    request.current.centre = Eigen::Vector3d(0.1 * (k + 1), 0, 0);
    const StereoBlock block = kemarRenderer().render(request);
    left.insert(left.end(), block.left.begin(), block.left.end());
  }
  const double amplitude = *std::max_element(left.begin() + 1000, left.end());
  // A 200 Hz sine of amplitude A steps by at most 2 pi 200 / 44100 A per sample.
  EXPECT_LT(largestStep(left), 1.1 * 2 * M_PI * 200 / kRate * amplitude);
}

TEST(RendererBlocks, TinyBlocksWithAJumpingHeadStayBounded) {
  REQUIRE_KEMAR();
  // The history before a block continues the head's motion backwards; a
  // block of a few samples whose head jumps 9.5 m, to the source or away
  // from it, must not extrapolate that into a burst.
  double largest_static = 0, largest_jumping = 0;
  for (const int samples : {1, 7, 64}) {
    for (const bool away : {false, true}) {
      BlockRequest request = staticScene(noise(), 30, 10.0, 44100, samples);
      request.current.centre = request.sources[0].position * 0.95;
      if (away) std::swap(request.previous, request.current);
      for (const HeadPose& pose : {request.previous, request.current}) {
        BlockRequest held = request;
        held.previous = held.current = pose;
        const StereoBlock still = kemarRenderer().render(held);
        for (float v : still.left) largest_static = std::max(largest_static, double(std::fabs(v)));
      }
      const StereoBlock jumping = kemarRenderer().render(request);
      for (float v : jumping.left) largest_jumping = std::max(largest_jumping, double(std::fabs(v)));
    }
  }
  EXPECT_GT(largest_static, 0);
  EXPECT_LT(largest_jumping, 3 * largest_static);
}

TEST(RendererRequests, RefusesWhatItCannotRender) {
  REQUIRE_KEMAR();
  const BinauralRenderer& renderer = kemarRenderer();
  const auto message = [&](const BlockRequest& request) {
    try {
      renderer.render(request);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  BlockRequest request = staticScene(noise(), 0, 2, 0, 100);
  request.num_samples = -1;
  EXPECT_NE(message(request).find("num_samples"), std::string::npos);
  request = staticScene(noise(), 0, 2, 0, 100);
  request.sources[0].occlusion = 1.5;
  EXPECT_NE(message(request).find("occlusion"), std::string::npos);
  request = staticScene(noise(), 0, 2, 0, 100);
  request.sources[0].position.x() = NAN;
  EXPECT_NE(message(request).find("position"), std::string::npos);
  request = staticScene(noise(), 0, 2, 0, 100);
  request.sources[0].signal = nullptr;
  EXPECT_NE(message(request).find("no signal"), std::string::npos);
  request = staticScene(noise(), 0, 2, 0, 100);
  request.current.yaw_deg = INFINITY;
  EXPECT_NE(message(request).find("current head pose"), std::string::npos);
  request = staticScene(noise(), 0, 2, 0, 100);
  request.noise_rms = -1;
  EXPECT_NE(message(request).find("noise_rms"), std::string::npos);
  EXPECT_THROW(BinauralRenderer(HrirSet::sphericalHead(48000), 44100), std::invalid_argument);
  // An empty block and a scene without sources are fine.
  request = staticScene(noise(), 0, 2, 0, 0);
  EXPECT_TRUE(renderer.render(request).left.empty());
  request = staticScene(noise(), 0, 2, -4410, 4410);
  request.sources.clear();
  request.noise_rms = 0;
  const StereoBlock silence = renderer.render(request);
  EXPECT_EQ(rms(silence.left), 0);
}

// Audio expert logic: acoustic occlusion O_a by lines from the source to
// the ears, the percepts, and the seeded position noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "lib/scene/acoustic_occlusion.hpp"
#include "experts/audio/audio_estimator.hpp"
#include "experts/audio/audio_expert.hpp"
#include "lib/expert/helper_task.hpp"
#include "lib/scene/object_geometry.hpp"
#include "experts/audio/position_noise.hpp"
#include "tests/experts/support/scene_builders.hpp"
#include "lib/scene/scene_geometry.hpp"

using namespace beft;

namespace {

double occlusionOf(const scene_objects_t& s, const robot_state_t& r, const std::string& id) {
  const auto solids = camera::SceneGeometry::fromMessage(s);
  for (std::size_t i = 0; i < s.objects.size(); ++i)
    if (s.objects[i].id == id)
      return audio::acousticOcclusion(solids, static_cast<int>(i), audio::sourceSamplePoints(s.objects[i]),
                                      geometry::leftEar(r), geometry::rightEar(r));
  throw std::runtime_error("no object " + id);
}

}  // namespace

TEST(AcousticOcclusion, NineSamplePointsInsideTheSourceOrOneForAPoint) {
  const auto box = test::boxObject("radio", "siren", 8, 5, 30, 0.4, 0.2, 0.3);
  const auto points = audio::sourceSamplePoints(box);
  ASSERT_EQ(points.size(), 9u);
  const double yaw = 30 * M_PI / 180;
  for (const auto& p : points) {
    const double along = (p.x() - 8) * std::cos(yaw) + (p.y() - 5) * std::sin(yaw);
    const double across = -(p.x() - 8) * std::sin(yaw) + (p.y() - 5) * std::cos(yaw);
    EXPECT_LT(std::abs(along), 0.2);
    EXPECT_LT(std::abs(across), 0.1);
    EXPECT_GT(p.z(), 0.0);
    EXPECT_LT(p.z(), 0.3);
  }
  const auto cylinder = test::cylinderObject("v", "person", 3, 3, 0.3, 1.8);
  const auto rim = audio::sourceSamplePoints(cylinder);
  ASSERT_EQ(rim.size(), 9u);
  for (const auto& p : rim) EXPECT_LT(std::hypot(p.x() - 3, p.y() - 3), 0.3);
  const auto point = audio::sourceSamplePoints(test::pointObject("radio", "siren", 4, 4, 0.5));
  ASSERT_EQ(point.size(), 1u);
  EXPECT_EQ(point[0], Eigen::Vector3d(4, 4, 0.5));
}

TEST(AcousticOcclusion, NothingBetweenGivesZeroAndTheSourceDoesNotBlockItself) {
  const auto s = test::scene({test::sounding(test::boxObject("radio", "siren", 8, 5, 0, 0.4, 0.4, 0.4), "ringing"),
                              test::boxObject("aside", "wall", 5, 9, 0, 0.2, 2, 3)});
  EXPECT_DOUBLE_EQ(occlusionOf(s, test::robot(2, 5, 0), "radio"), 0.0);
}

TEST(AcousticOcclusion, AWallBetweenSourceAndBothEarsGivesHundred) {
  const auto s = test::scene({test::sounding(test::boxObject("radio", "siren", 8, 5, 0, 0.4, 0.4, 0.4), "ringing"),
                              test::boxObject("wall", "wall", 5, 5, 0, 0.2, 6, 3)});
  EXPECT_DOUBLE_EQ(occlusionOf(s, test::robot(2, 5, 0), "radio"), 100.0);
  // Turning the head does not move the ears out of the wall's shadow.
  EXPECT_DOUBLE_EQ(occlusionOf(s, test::robot(2, 5, 0, 90), "radio"), 100.0);
}

TEST(AcousticOcclusion, OneEarBlockedGivesFifty) {
  // A point source at ear height 5 m ahead; a thin post 0.3 m in front of the
  // left ear (at y = 5.09) cuts the line to that ear only.
  const auto s = test::scene({test::sounding(test::pointObject("radio", "siren", 7, 5, 1.6), "ringing"),
                              test::boxObject("post", "wall", 2.3, 5.09, 0, 0.06, 0.06, 3)});
  EXPECT_DOUBLE_EQ(occlusionOf(s, test::robot(2, 5, 0), "radio"), 50.0);
  // Facing backwards swaps the ears: the post now shadows the right one.
  EXPECT_DOUBLE_EQ(occlusionOf(s, test::robot(2, 5, 180), "radio"), 50.0);
  // Head turned to +y: both ears on the line y = 5, clear of the post.
  EXPECT_DOUBLE_EQ(occlusionOf(s, test::robot(2, 5, 0, 90), "radio"), 0.0);
}

TEST(AudioEstimator, ReportsOnlySoundingObjectsWithLabelActivityAndTruePosition) {
  auto silent = test::sounding(test::pointObject("quiet", "siren", 1, 1), "ringing");
  silent.sound_active = false;
  auto radio = test::sounding(test::boxObject("radio", "siren", 8, 5, 0, 0.4, 0.4, 0.4), "playing", "person");
  radio.level = 0.7;
  const auto s = test::scene({test::sounding(test::cylinderObject("v", "person", 4, 8, 0.3, 1.8), "yelling"), silent,
                              radio, test::boxObject("wall", "wall", 5, 5, 0, 0.2, 6, 3)},
                             4);
  const auto solids = camera::SceneGeometry::fromMessage(s);
  const auto out = audio::estimateAudio(s, solids, test::robot(2, 5, 0), audio::AudioConfig{});
  EXPECT_EQ(out.tick, 4);
  ASSERT_EQ(out.num_percepts, 2);
  EXPECT_EQ(out.percepts[0].object_id, "v");
  EXPECT_EQ(out.percepts[0].acoustic_label, "person");  // no acoustic label: its category
  EXPECT_EQ(out.percepts[0].activity, "yelling");
  EXPECT_DOUBLE_EQ(out.percepts[0].occlusion, 0.0);
  EXPECT_DOUBLE_EQ(out.percepts[0].est_x, 4.0);
  EXPECT_DOUBLE_EQ(out.percepts[0].est_y, 8.0);
  EXPECT_TRUE(out.percepts[0].located);  // the simulator's position
  EXPECT_EQ(out.percepts[1].object_id, "radio");
  EXPECT_EQ(out.percepts[1].acoustic_label, "person");  // sounds like a person
  EXPECT_EQ(out.percepts[1].activity, "playing");
  EXPECT_DOUBLE_EQ(out.percepts[1].level, 0.7);
  EXPECT_DOUBLE_EQ(out.percepts[1].occlusion, 100.0);
}

TEST(PositionNoise, OffByDefaultDeterministicWhenOnAndWiderAtLowPerceptibility) {
  audio::PositionNoiseConfig off;
  EXPECT_EQ(audio::positionNoise(off, 3, "v", 0.1), Eigen::Vector2d::Zero());

  audio::PositionNoiseConfig on;
  on.enabled = true;
  on.seed = 7;
  on.max_sigma = 2.0;
  EXPECT_EQ(audio::positionNoise(on, 3, "v", 0.4), audio::positionNoise(on, 3, "v", 0.4));
  EXPECT_NE(audio::positionNoise(on, 3, "v", 0.4), audio::positionNoise(on, 4, "v", 0.4));
  EXPECT_NE(audio::positionNoise(on, 3, "v", 0.4), audio::positionNoise(on, 3, "w", 0.4));
  audio::PositionNoiseConfig other_seed = on;
  other_seed.seed = 8;
  EXPECT_NE(audio::positionNoise(on, 3, "v", 0.4), audio::positionNoise(other_seed, 3, "v", 0.4));
  EXPECT_EQ(audio::positionNoise(on, 3, "v", 1.0), Eigen::Vector2d::Zero());  // a_P = 1: exact

  // Per-axis spread sigma = 2 (1 - a_P): the RMS distance is sqrt(2) sigma.
  for (double a_p : {0.1, 0.5, 0.9}) {
    double sum_squares = 0;
    const int samples = 4000;
    for (int tick = 0; tick < samples; ++tick) sum_squares += audio::positionNoise(on, tick, "v", a_p).squaredNorm();
    const double rms = std::sqrt(sum_squares / samples);
    EXPECT_NEAR(rms, std::sqrt(2.0) * 2.0 * (1 - a_p), 0.05 * std::sqrt(2.0) * 2.0 * (1 - a_p)) << "a_P " << a_p;
  }
}

// The occlusions shared with a helper thread are those of one thread, in the
// same order, over random scenes of many sources behind walls.
TEST(AudioEstimator, HelperThreadGivesTheSamePercepts) {
  std::mt19937 random(9);
  std::uniform_real_distribution<double> position(0, 40), size(0.2, 4), angle(0, 360);
  expert::HelperTask helper;
  int occluded = 0;  // sources some line to an ear crosses another object: the scenes test something
  for (int scene_number = 0; scene_number < 20; ++scene_number) {
    std::vector<scene_object_t> objects;
    for (int i = 0; i < 120; ++i) {
      const std::string id = "o" + std::to_string(i);
      scene_object_t o = i % 2 ? test::boxObject(id, "wall", position(random), position(random), angle(random),
                                                 size(random), size(random) / 4, size(random))
                               : test::cylinderObject(id, "person", position(random), position(random), 0.3, 1.8);
      objects.push_back(i % 3 == 0 ? test::sounding(o, "yelling") : o);
    }
    const auto s = test::scene(objects, scene_number);
    const auto solids = camera::SceneGeometry::fromMessage(s);
    const auto robot = test::robot(position(random), position(random), angle(random), angle(random) - 180);
    const auto alone = audio::estimateAudio(s, solids, robot, audio::AudioConfig{});
    const auto helped = audio::estimateAudio(s, solids, robot, audio::AudioConfig{}, &helper);
    ASSERT_EQ(helped.num_percepts, alone.num_percepts);
    ASSERT_EQ(alone.num_percepts, 40);
    for (int k = 0; k < alone.num_percepts; ++k) {
      EXPECT_EQ(helped.percepts[k].object_id, alone.percepts[k].object_id);
      EXPECT_EQ(helped.percepts[k].occlusion, alone.percepts[k].occlusion) << alone.percepts[k].object_id;
      occluded += alone.percepts[k].occlusion > 0;
    }
  }
  EXPECT_GT(occluded, 100);
}

namespace {
std::vector<std::string> readChannels(const audio::AudioExpert& expert) {
  std::vector<std::string> names;
  for (const auto& spec : expert.reads()) names.push_back(spec.channel);
  return names;
}
}  // namespace

TEST(AudioExpert, ReadsTheEarsAndTheHypothesesOnlyWhenItHears) {
  audio::AudioExpert expert;
  expert.startUp({{"acoustics", "ground_truth"}});
  const auto ground_truth = readChannels(expert);
  for (const char* unread : {"EARS", "HYPOTHESES", "HYPOTHESIS_CHANGES"})
    EXPECT_EQ(std::count(ground_truth.begin(), ground_truth.end(), unread), 0) << unread << " is decoded for nothing";
  EXPECT_EQ(std::count(ground_truth.begin(), ground_truth.end(), "ROBOT_STATE"), 1);

  expert.startUp({{"acoustics", "binaural"}});
  const auto binaural = readChannels(expert);
  for (const char* read : {"EARS", "HYPOTHESES", "HYPOTHESIS_CHANGES", "ROBOT_STATE"})
    EXPECT_EQ(std::count(binaural.begin(), binaural.end(), read), 1) << read;
}

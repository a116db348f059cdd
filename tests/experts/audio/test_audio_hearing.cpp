// The audio expert's hearing (acoustics=binaural): bearings crossed into a
// position, and peaks of localised blocks given to the objects whose sounds
// they match, turned into world directions, front and back told apart.
#include <gtest/gtest.h>

#include <cmath>

#include "experts/audio/bearing_triangulation.hpp"
#include "experts/audio/heard_percepts.hpp"
#include "experts/audio/heard_sources.hpp"
#include "tests/experts/support/scene_builders.hpp"

using namespace beft;
using namespace beft::audio;

namespace {

double bearingTo(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  return std::atan2(to.y() - from.y(), to.x() - from.x()) * 180.0 / M_PI;
}

// A posterior with bumps (1-degree Gaussians of width sigma) at the given head-relative azimuths.
hearing::AzimuthPosterior bumps(const std::vector<std::pair<double, double>>& centre_and_weight, double sigma = 4) {
  std::array<double, hearing::AzimuthPosterior::kBins> values{};
  for (int a = 0; a < hearing::AzimuthPosterior::kBins; ++a) {
    for (const auto& [centre, weight] : centre_and_weight) {
      const double d = hearing::angularDistance(a, centre);
      values[static_cast<std::size_t>(a)] += weight * std::exp(-0.5 * d * d / (sigma * sigma));
    }
  }
  return hearing::AzimuthPosterior(values);
}

hearing::BandSignature spectrum(std::vector<double> bands) { return hearing::BandSignature{std::move(bands)}; }

hearing::BlockLocalisation heardAt(const std::vector<std::pair<double, const hearing::BandSignature*>>& peaks,
                                   double sigma = 4) {
  hearing::BlockLocalisation heard;
  std::vector<std::pair<double, double>> centres;
  for (const auto& [azimuth, signature] : peaks) {
    centres.emplace_back(azimuth, 1.0);
    hearing::LocalisedPeak peak;
    peak.azimuth_deg = azimuth;
    peak.weight = 1.0 / peaks.size();
    peak.signature = *signature;
    heard.peaks.push_back(peak);
  }
  heard.posterior = bumps(centres, sigma);
  heard.voting_frames = 7;
  return heard;
}

binaural_block_t blockAt(int64_t tick, double x, double y, double head_yaw) {
  binaural_block_t block{};
  block.tick = tick;
  block.utime = tick * 100000;
  block.sample_rate = 44100;
  block.head_x = x;
  block.head_y = y;
  block.head_yaw = head_yaw;
  block.full_scale = 1;
  return block;
}

}  // namespace

TEST(BearingTriangulation, CrossesLinesFromTwoPlacesAtTheSource) {
  const Eigen::Vector2d source(5, 3);
  const std::vector<BearingLine> lines = {{{0, 0}, bearingTo({0, 0}, source)}, {{2, -1}, bearingTo({2, -1}, source)},
                                          {{4, -1.5}, bearingTo({4, -1.5}, source)}};
  const auto crossing = triangulate(lines);
  ASSERT_TRUE(crossing.has_value());
  EXPECT_NEAR(crossing->x(), 5, 1e-9);
  EXPECT_NEAR(crossing->y(), 3, 1e-9);
}

TEST(BearingTriangulation, RefusesLinesThatHardlyCrossOrCrossBehind) {
  // Driving straight at the source: every line points the same way.
  EXPECT_FALSE(triangulate({{{0, 0}, 0.0}, {{1, 0}, 0.5}, {{2, 0}, -0.5}}).has_value());
  EXPECT_FALSE(triangulate({{{0, 0}, 45.0}}).has_value());
  // Two lines that meet only behind both places.
  EXPECT_FALSE(triangulate({{{0, 0}, 135.0}, {{4, 0}, 45.0}}).has_value());
  // The same two turned round meet in front, at (2, 2).
  const auto crossing = triangulate({{{0, 0}, 45.0}, {{4, 0}, 135.0}});
  ASSERT_TRUE(crossing.has_value());
  EXPECT_NEAR(crossing->y(), 2, 1e-9);
  EXPECT_FALSE(triangulate({{{0, 0}, std::nan("")}, {{4, 0}, 135.0}}).has_value());
}

TEST(HeardSources, GivesEachPeakToTheObjectWhoseSoundItMatches) {
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const auto siren = spectrum({0.1, 1, 10, 10, 1});
  HeardSources heard;
  const std::vector<SoundingObject> sounding = {{"victim", &voice}, {"siren", &siren}};
  // Head at (0, 0) facing +y (yaw 90): the voice 30 deg to the left, the siren 60 deg to the right.
  heard.hear(heardAt({{30, &voice}, {-60 + 360, &siren}}), blockAt(0, 0, 0, 90), sounding);
  const auto victim = heard.estimate("victim");
  const auto siren_heard = heard.estimate("siren");
  ASSERT_TRUE(victim && siren_heard);
  EXPECT_NEAR(victim->bearing_deg, 120, 1.0);
  EXPECT_NEAR(siren_heard->bearing_deg, 30, 1.0);
  EXPECT_FALSE(victim->triangulated);
  EXPECT_NEAR(victim->position.norm(), heard.config().default_distance_m, 1e-6);
  EXPECT_FALSE(heard.estimate("nobody").has_value());
}

// Two sirens sound alike: a peak from where vision placed one of them (or
// its front-back mirror image) is that one's, and the other, not seen yet,
// takes only what the seen one does not explain, whatever their order.
TEST(HeardSources, APeakFromWhereASeenObjectOfTheSameSoundIsIsThatObjects) {
  const auto siren = spectrum({0.1, 1, 10, 10, 1});
  const std::vector<SoundingObject> sounding = {{"siren_far", &siren}, {"siren_seen", &siren, Eigen::Vector2d(0, 10)}};
  // Head at (0, 0) facing +y: the seen siren straight ahead, the other 70 deg to the right.
  HeardSources heard;
  for (int tick = 0; tick < 5; ++tick)
    heard.hear(heardAt({{0, &siren}, {-70 + 360, &siren}}), blockAt(tick, 0, 0, 90), sounding);
  const auto far = heard.estimate("siren_far");
  const auto seen = heard.estimate("siren_seen");
  ASSERT_TRUE(far && seen);
  EXPECT_NEAR(far->bearing_deg, 20, 1.0);
  EXPECT_NEAR(seen->bearing_deg, 90, 1.0);

  // Only the seen siren's mirror image (behind the head): not the other's.
  HeardSources mirrored;
  mirrored.hear(heardAt({{180, &siren}}), blockAt(0, 0, 0, 90), sounding);
  EXPECT_FALSE(mirrored.estimate("siren_far").has_value());
  EXPECT_TRUE(mirrored.estimate("siren_seen").has_value());

  // Another sound, even a similar one, is told apart by its spectrum, from
  // wherever an object of that other sound was seen.
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const auto radio = spectrum({10, 9, 6, 2, 0.3});
  const double alike = hearing::signatureSimilarity(voice, radio);
  ASSERT_GE(alike, HearingConfig{}.min_similarity);
  ASSERT_LT(alike, 1.0);
  HeardSources voices;
  voices.hear(heardAt({{0, &voice}}), blockAt(0, 0, 0, 90),
              {{"victim", &voice}, {"radio_seen", &radio, Eigen::Vector2d(0, 10)}});
  ASSERT_TRUE(voices.estimate("victim").has_value());
  EXPECT_NEAR(voices.estimate("victim")->bearing_deg, 90, 1.0);
  EXPECT_FALSE(voices.estimate("radio_seen").has_value());

  // Neither seen: the first of equal scores takes the first peak, as before.
  HeardSources unseen;
  unseen.hear(heardAt({{0, &siren}, {-70 + 360, &siren}}), blockAt(0, 0, 0, 90),
              {{"siren_far", &siren}, {"siren_seen", &siren}});
  ASSERT_TRUE(unseen.estimate("siren_far").has_value());
  EXPECT_NEAR(unseen.estimate("siren_far")->bearing_deg, 90, 1.0);
}

// A seen object, even the only one of its sound, takes no peak from
// elsewhere: heard from far off, a nearer source of a like spectrum would
// pull its estimate away from where it was seen.
TEST(HeardSources, ASeenObjectTakesOnlyPeaksFromWhereItWasSeen) {
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const auto radio = spectrum({10, 9, 6, 2, 0.3});
  ASSERT_GE(hearing::signatureSimilarity(voice, radio), HearingConfig{}.min_similarity);
  // Head at (0, 0) facing +y; the victim was seen straight ahead.
  const std::vector<SoundingObject> seen = {{"victim", &voice, Eigen::Vector2d(0, 10)}};
  HeardSources heard;
  heard.hear(heardAt({{60, &radio}}), blockAt(0, 0, 0, 90), seen);
  EXPECT_FALSE(heard.estimate("victim").has_value()) << "a like sound 60 deg off is not the seen victim";
  heard.hear(heardAt({{5, &voice}}), blockAt(1, 0, 0, 90), seen);
  ASSERT_TRUE(heard.estimate("victim").has_value());
  EXPECT_NEAR(heard.estimate("victim")->bearing_deg, 95, 1.0);
  // Not seen, the same peak 60 deg off is its.
  HeardSources unseen;
  unseen.hear(heardAt({{60, &radio}}), blockAt(0, 0, 0, 90), {{"victim", &voice}});
  ASSERT_TRUE(unseen.estimate("victim").has_value());
  EXPECT_NEAR(unseen.estimate("victim")->bearing_deg, 150, 1.0);
  // With the gate off, the seen one takes it too.
  HearingConfig off;
  off.seen_explains_deg = 0;
  HeardSources ungated(off);
  ungated.hear(heardAt({{60, &radio}}), blockAt(0, 0, 0, 90), seen);
  EXPECT_TRUE(ungated.estimate("victim").has_value());
}

TEST(HeardSources, APeakLikeNoSoundingObjectIsNotAssigned) {
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const auto engine = spectrum({0.1, 0.1, 1, 8, 10});
  HeardSources heard;
  heard.hear(heardAt({{30, &engine}}), blockAt(0, 0, 0, 0), {{"victim", &voice}});
  EXPECT_FALSE(heard.estimate("victim").has_value());
}

TEST(HeardSources, ATurningHeadTellsFrontFromBackAndAsksForATurnMeanwhile) {
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const std::vector<SoundingObject> sounding = {{"victim", &voice}};
  HeardSources heard;
  // The source is behind-left at world bearing 150 (head yaw 0): heard at 150 and at its mirror 30.
  for (int tick = 0; tick < 10; ++tick) heard.hear(heardAt({{150, &voice}, {30, &voice}}), blockAt(tick, 0, 0, 0), sounding);
  std::string who;
  const auto turn = heard.wantsHeadTurn(0, 80, 0, &who);
  ASSERT_TRUE(turn.has_value());
  EXPECT_EQ(who, "victim");
  EXPECT_NEAR(*turn, heard.config().turn_deg, 1e-9);
  EXPECT_FALSE(heard.wantsHeadTurn(0, 80, 100000, &who).has_value()) << "one turn per turn_interval_s";
  // Near the limit the head turns the other way.
  HeardSources near_limit;
  near_limit.hear(heardAt({{150, &voice}, {30, &voice}}), blockAt(0, 0, 0, 0), sounding);
  EXPECT_NEAR(*near_limit.wantsHeadTurn(75, 80, 0, &who), 75 - near_limit.config().turn_deg, 1e-9);

  // After a 20-degree turn to the left the true source is at head-relative
  // 130, its mirror at 50: in the world 150 (agrees) and 70 (moved).
  for (int tick = 10; tick < 20; ++tick) heard.hear(heardAt({{130, &voice}, {50, &voice}}), blockAt(tick, 0, 0, 20), sounding);
  const auto victim = heard.estimate("victim");
  ASSERT_TRUE(victim.has_value());
  EXPECT_NEAR(victim->bearing_deg, 150, 2.0);
  EXPECT_FALSE(heard.wantsHeadTurn(20, 80, 10000000, &who).has_value()) << "resolved: no more turns";
}

TEST(HeardSources, TriangulatesOverTheRobotsOwnMotion) {
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const std::vector<SoundingObject> sounding = {{"victim", &voice}};
  const Eigen::Vector2d source(6, 4);
  HeardSources heard;
  // The robot drives along +x facing +x (yaw 0), hearing the source to its left (sharp, unambiguous: no mirror).
  for (int tick = 0; tick <= 80; ++tick) {
    const Eigen::Vector2d at(0.1 * tick, 0);
    const double azimuth = bearingTo(at, source);
    heard.hear(heardAt({{azimuth, &voice}}, 2), blockAt(tick, at.x(), at.y(), 0), sounding);
  }
  const auto victim = heard.estimate("victim");
  ASSERT_TRUE(victim.has_value());
  ASSERT_TRUE(victim->triangulated);
  EXPECT_LT((victim->position - source).norm(), 0.5);
}

namespace {

constexpr int kTicksPerSecond = 10;  // blockAt: 0.1 s a tick

// Drives from `from` to `to` in steps of 0.1 m a tick (yaw 0), hearing a
// sharp, unambiguous source at `source`; returns the next tick.
int driveHearing(HeardSources& heard, const std::vector<SoundingObject>& sounding, const hearing::BandSignature& voice,
                 int tick, const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Eigen::Vector2d& source) {
  const int steps = static_cast<int>(std::round((to - from).norm() / 0.1));
  for (int step = 0; step <= steps; ++step, ++tick) {
    const Eigen::Vector2d at = from + (to - from) * (steps == 0 ? 0.0 : static_cast<double>(step) / steps);
    heard.hear(heardAt({{bearingTo(at, source), &voice}}, 2), blockAt(tick, at.x(), at.y(), 0), sounding);
  }
  return tick;
}

}  // namespace

TEST(HeardSources, FarFromTheSourceTheEstimateStaysWhereTheBearingsCrossed) {
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const std::vector<SoundingObject> sounding = {{"radio", &voice}};
  const Eigen::Vector2d source(6, 4);
  HeardSources heard;
  int tick = driveHearing(heard, sounding, voice, 0, {0, 0}, {8, 0}, source);
  ASSERT_TRUE(heard.estimate("radio")->triangulated);
  // Then 40 m on, where it stays for longer than a line is kept: the lines
  // that crossed age out, and from there no two places see it at angles
  // that differ enough to cross.
  const auto driveAwayAndStay = [&](HeardSources& hearing, int at_tick) {
    at_tick = driveHearing(hearing, sounding, voice, at_tick, {8, 0}, {48, 0}, source);
    for (int held = 0; held < kTicksPerSecond * 1.5 * hearing.config().line_max_age_s; ++held)
      at_tick = driveHearing(hearing, sounding, voice, at_tick, {48, 0}, {48, 0}, source);
  };
  driveAwayAndStay(heard, tick);
  const auto radio = heard.estimate("radio");
  ASSERT_TRUE(radio.has_value());
  EXPECT_TRUE(radio->triangulated);
  EXPECT_LT((radio->position - source).norm(), 0.5) << "not default_distance_m from the robot";
  // Without a kept fix (an agreement of 0 degrees drops it at once) the
  // estimate falls back to default_distance_m from where it was heard.
  HearingConfig no_fix;
  no_fix.fix_agreement_deg = 0;
  HeardSources forgetful(no_fix);
  driveAwayAndStay(forgetful, driveHearing(forgetful, sounding, voice, 0, {0, 0}, {8, 0}, source));
  EXPECT_GT((forgetful.estimate("radio")->position - source).norm(), 30);
}

TEST(HeardSources, AFixTheHeardDirectionNoLongerPointsAtIsDropped) {
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const std::vector<SoundingObject> sounding = {{"walker", &voice}};
  HeardSources heard;
  int tick = driveHearing(heard, sounding, voice, 0, {0, 0}, {8, 0}, {6, 4});
  // The robot stands there until the lines that crossed have aged out; the fix is kept.
  for (int held = 0; held < kTicksPerSecond * 1.5 * heard.config().line_max_age_s; ++held)
    tick = driveHearing(heard, sounding, voice, tick, {8, 0}, {8, 0}, {6, 4});
  ASSERT_LT((heard.estimate("walker")->position - Eigen::Vector2d(6, 4)).norm(), 0.5);
  // The walker is now far to the other side, and heard there.
  const Eigen::Vector2d moved(8, -12);
  for (int held = 0; held < 30; ++held) tick = driveHearing(heard, sounding, voice, tick, {8, 0}, {8, 0}, moved);
  const auto walker = heard.estimate("walker");
  ASSERT_TRUE(walker.has_value());
  EXPECT_GT((walker->position - Eigen::Vector2d(6, 4)).norm(), 5) << "the old fix is dropped";
  EXPECT_LE(hearing::angularDistance(walker->bearing_deg, -90), 3);
}

// The percept says whether its estimate is located: a point along the first
// bearing at an assumed range is not, a crossing of bearings is.
TEST(HeardSources, APerceptIsLocatedOnlyOnceItsBearingsCrossed) {
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const std::vector<SoundingObject> sounding = {{"victim", &voice}};
  const Eigen::Vector2d source(6, 4);
  const scene_objects_t scene =
      test::scene({test::sounding(test::cylinderObject("victim", "person", source.x(), source.y(), 0.3, 1.8), "yelling")}, 0);
  const auto solids = camera::SceneGeometry::fromMessage(scene);
  HeardSources heard;
  heard.hear(heardAt({{bearingTo({0, 0}, source), &voice}}, 2), blockAt(0, 0, 0, 0), sounding);
  acoustic_percepts_t percepts = heardPercepts(scene, solids, test::robot(0, 0, 0), heard);
  ASSERT_EQ(percepts.num_percepts, 1);
  EXPECT_FALSE(percepts.percepts[0].located);

  for (int tick = 1; tick <= 80; ++tick) {
    const Eigen::Vector2d at(0.1 * tick, 0);
    heard.hear(heardAt({{bearingTo(at, source), &voice}}, 2), blockAt(tick, at.x(), at.y(), 0), sounding);
  }
  percepts = heardPercepts(scene, solids, test::robot(8, 0, 0), heard);
  ASSERT_EQ(percepts.num_percepts, 1);
  EXPECT_TRUE(percepts.percepts[0].located);
  EXPECT_LT(std::hypot(percepts.percepts[0].est_x - source.x(), percepts.percepts[0].est_y - source.y()), 0.5);
}

TEST(BearingTriangulation, ACrossingFromFarOrFromOneSideIsLessCertainThanOneFromUpClose) {
  const Eigen::Vector2d source(6, 4);
  const auto linesFrom = [&](const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
    std::vector<BearingLine> lines;
    for (int step = 0; step <= 20; ++step) {
      const Eigen::Vector2d at = from + (to - from) * step / 20.0;
      lines.push_back({at, bearingTo(at, source)});
    }
    return lines;
  };
  const double near = crossingError(linesFrom({0, 0}, {8, 0}), source, 3);
  const double far = crossingError(linesFrom({21, -6}, {21, 6}), source, 3);
  const double one_side = crossingError(linesFrom({0, 0}, {0.5, 0}), source, 3);
  EXPECT_LT(near, 1.0);
  EXPECT_GT(far, 4 * near);
  EXPECT_GT(one_side, 2 * far);
  // The error is that of the mean line: the same lines twice are no better.
  auto twice = linesFrom({0, 0}, {8, 0});
  const auto again = linesFrom({0, 0}, {8, 0});
  twice.insert(twice.end(), again.begin(), again.end());
  EXPECT_NEAR(crossingError(twice, source, 3), near, 1e-9);
  EXPECT_NEAR(crossingError(linesFrom({0, 0}, {8, 0}), source, 6), 2 * near, 1e-9) << "in proportion to the bearing error";
  // Parallel lines do not cross.
  EXPECT_TRUE(std::isinf(crossingError({{{0, 0}, 90.0}, {{1, 0}, 90.0}}, {0, 5}, 3)));
}

// Bearings heard from far away that all err alike (here by 5 degrees) cross
// away from the source: they do not replace a crossing made up close while
// the source is still heard there.
TEST(HeardSources, ACrossingMadeUpCloseIsNotReplacedByAWorseOneFromFarAway) {
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const std::vector<SoundingObject> sounding = {{"siren", &voice}};
  const Eigen::Vector2d source(6, 4);
  const auto run = [&](const HearingConfig& config) {
    HeardSources heard(config);
    int tick = driveHearing(heard, sounding, voice, 0, {0, 0}, {8, 0}, source);
    EXPECT_LT((heard.estimate("siren")->position - source).norm(), 0.5);
    // Then to and fro 15 m east of it, hearing it 5 degrees off, until the
    // lines from up close have aged out.
    const auto biasedDrive = [&](Eigen::Vector2d from, Eigen::Vector2d to) {
      const int steps = static_cast<int>(std::round((to - from).norm() / 0.1));
      for (int step = 0; step <= steps; ++step, ++tick) {
        const Eigen::Vector2d at = from + (to - from) * static_cast<double>(step) / steps;
        heard.hear(heardAt({{bearingTo(at, source) + 5, &voice}}, 2), blockAt(tick, at.x(), at.y(), 0), sounding);
      }
    };
    biasedDrive({8, 0}, {21, -6});
    for (int pass = 0; pass < 2; ++pass) {
      biasedDrive({21, -6}, {21, 6});
      biasedDrive({21, 6}, {21, -6});
    }
    EXPECT_GT(tick, kTicksPerSecond * config.line_max_age_s + 100) << "the lines from up close aged out";
    const auto estimate = heard.estimate("siren");
    EXPECT_TRUE(estimate.has_value() && estimate->triangulated);
    return estimate ? (estimate->position - source).norm() : 1e9;
  };
  HearingConfig newest_crossing_wins;
  newest_crossing_wins.fix_aging_mps = 1e6;
  const double kept_close = run(HearingConfig{}), newest = run(newest_crossing_wins);
  EXPECT_LT(kept_close, 1.0);
  EXPECT_GT(newest, 1.5) << "the far crossing is worse: the test must show it";
  EXPECT_GT(newest, 2 * kept_close);
}

// Many bearings from far away that err alike, a few exact ones from up
// close: weighted by their distance, the close ones decide where they cross.
TEST(BearingTriangulation, LinesHeardUpCloseOutweighManyFromFarAway) {
  const Eigen::Vector2d source(6, 4);
  std::vector<BearingLine> lines;
  for (int step = 0; step <= 5; ++step) {
    const Eigen::Vector2d at(1.6 * step, 0);
    lines.push_back({at, bearingTo(at, source)});
  }
  for (int step = 0; step < 34; ++step) {
    const Eigen::Vector2d at(21, -6 + 12.0 * step / 33);
    lines.push_back({at, bearingTo(at, source) + 5});
  }
  const auto weighted = triangulate(lines);
  TriangulationLimits alike;
  alike.reweighting_passes = 0;
  const auto unweighted = triangulate(lines, alike);
  ASSERT_TRUE(weighted && unweighted);
  EXPECT_LT((*weighted - source).norm(), 0.5);
  EXPECT_GT((*unweighted - source).norm(), 2 * (*weighted - source).norm());
}

// Heard from elsewhere for a moment (a mirror image, a peak of another
// source), the fix stays; heard elsewhere for longer than
// fix_disagreement_s, it is dropped.
TEST(HeardSources, AMomentsMissDoesNotDropTheFixALastingOneDoes) {
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const std::vector<SoundingObject> sounding = {{"siren", &voice}};
  const Eigen::Vector2d source(6, 4);
  HeardSources heard;
  int tick = driveHearing(heard, sounding, voice, 0, {0, 0}, {8, 0}, source);
  const auto hearFrom = [&](const Eigen::Vector2d& direction_of, int ticks) {
    for (int held = 0; held < ticks; ++held) tick = driveHearing(heard, sounding, voice, tick, {8, 0}, {8, 0}, direction_of);
  };
  // Standing still until the lines that crossed have aged out: the fix alone says where.
  hearFrom(source, static_cast<int>(1.5 * heard.config().line_max_age_s * kTicksPerSecond));
  ASSERT_TRUE(heard.estimate("siren")->triangulated);
  const Eigen::Vector2d fix = heard.estimate("siren")->position;
  ASSERT_LT((fix - source).norm(), 1.0);
  const Eigen::Vector2d elsewhere(8, -12);
  hearFrom(elsewhere, static_cast<int>(0.5 * heard.config().fix_disagreement_s * kTicksPerSecond));
  hearFrom(source, kTicksPerSecond);
  ASSERT_TRUE(heard.estimate("siren")->triangulated);
  EXPECT_LT((heard.estimate("siren")->position - fix).norm(), 0.1) << "kept through a moment's miss";
  hearFrom(elsewhere, static_cast<int>(1.5 * heard.config().fix_disagreement_s * kTicksPerSecond));
  EXPECT_GT((heard.estimate("siren")->position - source).norm(), 3) << "dropped after a lasting one";
  // With no time to disagree, the moment's miss drops it.
  HearingConfig at_once;
  at_once.fix_disagreement_s = 0;
  HeardSources hasty(at_once);
  tick = driveHearing(hasty, sounding, voice, 0, {0, 0}, {8, 0}, source);
  for (int held = 0; held < 1.5 * heard.config().line_max_age_s * kTicksPerSecond; ++held)
    tick = driveHearing(hasty, sounding, voice, tick, {8, 0}, {8, 0}, source);
  for (int held = 0; held < 0.5 * heard.config().fix_disagreement_s * kTicksPerSecond; ++held)
    tick = driveHearing(hasty, sounding, voice, tick, {8, 0}, {8, 0}, elsewhere);
  EXPECT_GT((hasty.estimate("siren")->position - fix).norm(), 3);
}

// A walker heard elsewhere for longer than fix_disagreement_s: the lines
// that placed it before go with the dropped fix, and the new ones alone say
// where it is now.
TEST(HeardSources, TheLinesOfADroppedFixDoNotPullTheNextOne) {
  const auto voice = spectrum({10, 8, 4, 1, 0.1});
  const std::vector<SoundingObject> sounding = {{"walker", &voice}};
  const Eigen::Vector2d before(6, 4), now(14, 4);
  const auto run = [&](const HearingConfig& config) {
    HeardSources heard(config);
    int tick = driveHearing(heard, sounding, voice, 0, {0, 0}, {8, 0}, before);
    EXPECT_LT((heard.estimate("walker")->position - before).norm(), 1.0);
    tick = driveHearing(heard, sounding, voice, tick, {8, 0}, {12, 0}, now);  // with the old lines: 8 m off
    const auto estimate = heard.estimate("walker");
    return estimate && estimate->triangulated ? (estimate->position - now).norm() : 1e9;
  };
  EXPECT_LT(run(HearingConfig{}), 0.5);
}

// Fusion logic: hypotheses kept across ticks, verified and falsified
// sequences, the fused confidences and the position source.
#include <gtest/gtest.h>

#include "experts/fusion/hypothesis_fusion.hpp"
#include "lib/model/model.hpp"
#include "tests/experts/support/scene_builders.hpp"

using namespace beft;

namespace {

const std::vector<std::string> kCategories = {"person", "car", "siren", "wall", "fire"};

object_labels_t labelsFor(const std::string& id, const std::string& label, double perceptibility) {
  object_labels_t entry{};
  entry.object_id = id;
  entry.perceptibility = perceptibility;
  entry.categories = kCategories;
  entry.num_categories = static_cast<int32_t>(kCategories.size());
  entry.confidence = model::labelConfidences(kCategories, label, perceptibility);
  return entry;
}

// One tick of percepts, built up by the tests.
struct Tick {
  scene_objects_t scene{};
  visual_percepts_t vision{};
  labels_t visual_labels{};
  acoustic_percepts_t audio{};
  labels_t acoustic_labels{};

  Tick(const std::vector<scene_object_t>& objects, int64_t tick) : scene(test::scene(objects, tick)) {
    vision.tick = visual_labels.tick = audio.tick = acoustic_labels.tick = tick;
  }
  // Vision reports every object with a visual; this one with its pixels and v_P.
  Tick& seen(const std::string& id, const std::string& label, int visible_pixels, double v_p) {
    visual_percept_t p{};
    p.object_id = id;
    p.visible_pixels = visible_pixels;
    p.expected_pixels = 100;
    p.occlusion = 100.0 - visible_pixels;
    vision.percepts.push_back(p);
    vision.num_percepts = static_cast<int32_t>(vision.percepts.size());
    visual_labels.objects.push_back(labelsFor(id, label, v_p));
    visual_labels.num_objects = static_cast<int32_t>(visual_labels.objects.size());
    return *this;
  }
  // located: the estimate is a crossing of bearings (false: a point along one).
  Tick& heard(const std::string& id, const std::string& label, double a_p, double x, double y, bool located = true) {
    acoustic_percept_t p{};
    p.object_id = id;
    p.est_x = x;
    p.est_y = y;
    p.located = located;
    p.acoustic_label = label;
    audio.percepts.push_back(p);
    audio.num_percepts = static_cast<int32_t>(audio.percepts.size());
    acoustic_labels.objects.push_back(labelsFor(id, label, a_p));
    acoustic_labels.num_objects = static_cast<int32_t>(acoustic_labels.objects.size());
    return *this;
  }
  fusion::TickEvidence evidence() const { return {&scene, &vision, &visual_labels, &audio, &acoustic_labels}; }
};

const hypothesis_t* find(const hypotheses_t& all, const std::string& id) {
  for (const auto& h : all.hypotheses)
    if (h.object_id == id) return &h;
  return nullptr;
}

double fusedOf(const hypothesis_t& h, const std::string& category) {
  for (int j = 0; j < h.num_categories; ++j)
    if (h.categories[j] == category) return h.fused[j];
  throw std::runtime_error("no category " + category);
}

}  // namespace

TEST(Fusion, HeardThenSeenAsTheSameIsVerified) {
  const std::vector<scene_object_t> objects = {
      test::sounding(test::cylinderObject("victim", "person", 10, 5, 0.3, 1.8), "yelling"),
      test::boxObject("wall", "wall", 8, 5, 90, 4, 0.2, 2.5)};
  fusion::HypothesisFusion fusion;

  // Tick 0: heard behind the wall, not visible.
  fusion.update(Tick(objects, 0).seen("victim", "person", 0, 0.0).heard("victim", "person", 0.3, 10.4, 5.3).evidence());
  auto out = fusion.hypotheses(0, 0);
  ASSERT_EQ(out.num_hypotheses, 1);  // the wall is not in view: no hypothesis for it
  const hypothesis_t* h = find(out, "victim");
  ASSERT_NE(h, nullptr);
  EXPECT_TRUE(h->heard);
  EXPECT_FALSE(h->seen);
  EXPECT_EQ(h->heard_as, "person");
  EXPECT_EQ(h->seen_as, "");
  EXPECT_FALSE(h->verified);
  EXPECT_FALSE(h->falsified);
  EXPECT_DOUBLE_EQ(h->x, 10.4);  // acoustic estimate while not seen
  EXPECT_DOUBLE_EQ(h->y, 5.3);
  EXPECT_EQ(h->first_heard_utime, 0);
  EXPECT_EQ(h->first_seen_utime, -1);
  EXPECT_EQ(h->settled_utime, -1);
  EXPECT_EQ(h->best_category, "person");

  // Tick 1: silent, a sliver visible (v_P below the threshold): not seen yet,
  // but vision now places it.
  fusion.update(Tick(objects, 1).seen("victim", "person", 5, 0.3).evidence());
  h = find(out = fusion.hypotheses(100000, 1), "victim");
  ASSERT_NE(h, nullptr);
  EXPECT_FALSE(h->seen);
  EXPECT_TRUE(h->heard);  // stays heard after falling silent
  EXPECT_FALSE(h->verified);
  EXPECT_DOUBLE_EQ(h->x, 10.0);
  EXPECT_DOUBLE_EQ(h->y, 5.0);

  // Tick 2: in clear view.
  fusion.update(Tick(objects, 2).seen("victim", "person", 90, 0.8).evidence());
  h = find(out = fusion.hypotheses(200000, 2), "victim");
  ASSERT_NE(h, nullptr);
  EXPECT_TRUE(h->seen);
  EXPECT_EQ(h->seen_as, "person");
  EXPECT_TRUE(h->verified);
  EXPECT_FALSE(h->falsified);
  EXPECT_EQ(h->first_seen_utime, 200000);
  EXPECT_EQ(h->settled_utime, 200000);
  EXPECT_EQ(h->first_heard_utime, 0);

  // Tick 3: nothing perceived at all; the hypothesis and its verdict stay.
  fusion.update(Tick(objects, 3).evidence());
  h = find(out = fusion.hypotheses(300000, 3), "victim");
  ASSERT_NE(h, nullptr);
  EXPECT_TRUE(h->verified);
  EXPECT_EQ(h->settled_utime, 200000);
}

// A heard estimate along a bearing at an assumed range is not located; a
// crossing is, and a place vision gives is.
TEST(Fusion, APositionIsLocatedOnceTheBearingsCrossOrItIsSeen) {
  const std::vector<scene_object_t> objects = {
      test::sounding(test::cylinderObject("victim", "person", 10, 5, 0.3, 1.8), "yelling")};
  fusion::HypothesisFusion fusion;
  fusion.update(Tick(objects, 0).heard("victim", "person", 0.3, 4, 0, false).evidence());
  hypotheses_t out = fusion.hypotheses(0, 0);
  ASSERT_NE(find(out, "victim"), nullptr);
  EXPECT_FALSE(find(out, "victim")->located);

  fusion.update(Tick(objects, 1).heard("victim", "person", 0.3, 10.4, 5.3, true).evidence());
  out = fusion.hypotheses(100000, 1);
  EXPECT_TRUE(find(out, "victim")->located);
  EXPECT_DOUBLE_EQ(find(out, "victim")->x, 10.4);

  fusion.update(Tick(objects, 2).heard("victim", "person", 0.3, 6, 1, false).evidence());
  out = fusion.hypotheses(200000, 2);
  EXPECT_FALSE(find(out, "victim")->located);

  fusion.update(Tick(objects, 3).seen("victim", "person", 5, 0.3).heard("victim", "person", 0.3, 6, 1, false).evidence());
  out = fusion.hypotheses(300000, 3);
  EXPECT_TRUE(find(out, "victim")->located);  // vision placed it
  EXPECT_DOUBLE_EQ(find(out, "victim")->x, 10.0);
}

TEST(Fusion, RadioThatSoundsLikeAPersonButLooksLikeASirenIsFalsified) {
  const std::vector<scene_object_t> objects = {
      test::sounding(test::boxObject("radio", "siren", 12, 6, 0, 0.4, 0.3, 0.3), "playing", "person")};
  fusion::HypothesisFusion fusion;
  fusion.update(Tick(objects, 0).seen("radio", "siren", 0, 0.0).heard("radio", "person", 0.6, 12, 6).evidence());
  auto out = fusion.hypotheses(0, 0);
  const hypothesis_t* h = find(out, "radio");
  ASSERT_NE(h, nullptr);
  EXPECT_EQ(h->best_category, "person");  // only heard so far
  EXPECT_FALSE(h->falsified);

  fusion.update(Tick(objects, 1).seen("radio", "siren", 80, 0.9).heard("radio", "person", 0.2, 12, 6).evidence());
  h = find(out = fusion.hypotheses(100000, 1), "radio");
  ASSERT_NE(h, nullptr);
  EXPECT_EQ(h->heard_as, "person");
  EXPECT_EQ(h->seen_as, "siren");
  EXPECT_TRUE(h->falsified);
  EXPECT_FALSE(h->verified);
  EXPECT_EQ(h->settled_utime, 100000);
  // Perceptibility-weighted average of the best evidence: acoustic 0.6 (the
  // later 0.2 is weaker and does not replace it), visual 0.9.
  const auto acoustic = model::labelConfidences(kCategories, "person", 0.6);
  const auto visual = model::labelConfidences(kCategories, "siren", 0.9);
  EXPECT_NEAR(fusedOf(*h, "person"), (0.6 * acoustic[0] + 0.9 * visual[0]) / 1.5, 1e-12);
  EXPECT_NEAR(fusedOf(*h, "siren"), (0.6 * acoustic[2] + 0.9 * visual[2]) / 1.5, 1e-12);
  EXPECT_EQ(h->best_category, "siren");
  EXPECT_NEAR(h->confidence, fusedOf(*h, "siren"), 1e-12);
}

TEST(Fusion, SeenButNeverHeardIsNeitherVerifiedNorFalsified) {
  const std::vector<scene_object_t> objects = {test::boxObject("car1", "car", 5, 5, 0, 4, 2, 1.5),
                                               test::cylinderObject("v", "person", 9, 9, 0.3, 1.8)};
  fusion::HypothesisFusion fusion;
  fusion.update(Tick(objects, 0).seen("car1", "car", 50, 0.7).seen("v", "person", 20, 0.6).evidence());
  const auto out = fusion.hypotheses(0, 0);
  ASSERT_EQ(out.num_hypotheses, 2);
  EXPECT_EQ(out.hypotheses[0].object_id, "car1");  // scenario order within a tick
  EXPECT_EQ(out.hypotheses[1].object_id, "v");
  for (const auto& h : out.hypotheses) {
    EXPECT_TRUE(h.seen);
    EXPECT_FALSE(h.heard);
    EXPECT_FALSE(h.verified);
    EXPECT_FALSE(h.falsified);
    EXPECT_EQ(h.settled_utime, -1);
  }
  // Only vision: the fused confidences are the visual ones.
  EXPECT_EQ(out.hypotheses[0].fused, model::labelConfidences(kCategories, "car", 0.7));
}

TEST(Fusion, SeenThresholdIsAParameter) {
  const std::vector<scene_object_t> objects = {
      test::sounding(test::cylinderObject("v", "person", 9, 9, 0.3, 1.8), "yelling")};
  fusion::FusionConfig strict;
  strict.seen_threshold = 0.9;
  fusion::HypothesisFusion fusion(strict);
  fusion.update(Tick(objects, 0).seen("v", "person", 60, 0.8).heard("v", "person", 0.5, 9, 9).evidence());
  const auto out = fusion.hypotheses(0, 0);
  ASSERT_EQ(out.num_hypotheses, 1);
  EXPECT_FALSE(out.hypotheses[0].seen);
  EXPECT_FALSE(out.hypotheses[0].verified);
}

// The radio case: seen as a siren at v_P = 0.8, heard as a person at a_P = 0.6.
hypothesis_t fusedRadio(fusion::FusionRule rule) {
  const std::vector<scene_object_t> objects = {
      test::sounding(test::cylinderObject("radio", "siren", 9, 9, 0.3, 1.0), "ringing")};
  fusion::FusionConfig config;
  config.rule = rule;
  fusion::HypothesisFusion fusion(config);
  fusion.update(Tick(objects, 0).seen("radio", "siren", 80, 0.8).heard("radio", "person", 0.6, 9, 9).evidence());
  return fusion.hypotheses(0, 0).hypotheses.at(0);
}

TEST(Fusion, EachFusionRuleGivesItsNumbers) {
  // L_j of eq. 3 for each modality, as the labellers compute them.
  const double seen_siren = model::labelConfidences(kCategories, "siren", 0.8)[2];
  const double seen_person = model::labelConfidences(kCategories, "siren", 0.8)[0];
  const double heard_siren = model::labelConfidences(kCategories, "person", 0.6)[2];
  const double heard_person = model::labelConfidences(kCategories, "person", 0.6)[0];
  ASSERT_EQ(kCategories[0], "person");
  ASSERT_EQ(kCategories[2], "siren");

  const auto weighted = fusedRadio(fusion::FusionRule::WeightedMean);
  EXPECT_NEAR(fusedOf(weighted, "siren"), (0.8 * seen_siren + 0.6 * heard_siren) / 1.4, 1e-12);
  EXPECT_NEAR(fusedOf(weighted, "person"), (0.8 * seen_person + 0.6 * heard_person) / 1.4, 1e-12);
  EXPECT_EQ(weighted.best_category, "siren");

  const auto mean = fusedRadio(fusion::FusionRule::Mean);
  EXPECT_NEAR(fusedOf(mean, "siren"), (seen_siren + heard_siren) / 2, 1e-12);
  EXPECT_NEAR(fusedOf(mean, "person"), (seen_person + heard_person) / 2, 1e-12);

  const auto clearest = fusedRadio(fusion::FusionRule::Clearest);
  EXPECT_NEAR(fusedOf(clearest, "siren"), seen_siren, 1e-12);
  EXPECT_NEAR(fusedOf(clearest, "person"), seen_person, 1e-12);
  // The verdicts do not depend on the rule: seen as a siren, heard as a person.
  for (const auto& h : {weighted, mean, clearest}) EXPECT_TRUE(h.falsified);
}

TEST(Fusion, SeenNeedsTheThresholdSoNothingBeyondTenMetresCountsAtTheDefault) {
  EXPECT_DOUBLE_EQ(fusion::FusionConfig{}.seen_threshold, 0.5);
  // v_P = g_d(d) * v_o: unoccluded at 10 m is exactly 0.5, a little further is less.
  EXPECT_NEAR(model::distanceDegradation(10.0), 0.5, 1e-12);
  const std::vector<scene_object_t> objects = {
      test::sounding(test::cylinderObject("v", "person", 9, 9, 0.3, 1.8), "yelling")};
  for (const auto& [v_p, seen] : {std::pair{0.5, true}, {model::distanceDegradation(10.2), false}, {0.49999, false}}) {
    fusion::HypothesisFusion fusion;
    fusion.update(Tick(objects, 0).seen("v", "person", 60, v_p).heard("v", "person", 0.5, 9, 9).evidence());
    EXPECT_EQ(fusion.hypotheses(0, 0).hypotheses.at(0).seen, seen) << "v_P = " << v_p;
  }
}

TEST(Fusion, FusesWhatArrivedWhenAModalityIsMissing) {
  const std::vector<scene_object_t> objects = {
      test::sounding(test::cylinderObject("v", "person", 9, 9, 0.3, 1.8), "yelling")};
  Tick tick(objects, 0);
  tick.heard("v", "person", 0.5, 8.5, 9);
  fusion::TickEvidence evidence = tick.evidence();
  evidence.vision = nullptr;
  evidence.visual_labels = nullptr;
  fusion::HypothesisFusion fusion;
  fusion.update(evidence);
  const auto out = fusion.hypotheses(0, 0);
  ASSERT_EQ(out.num_hypotheses, 1);
  EXPECT_TRUE(out.hypotheses[0].heard);
  EXPECT_DOUBLE_EQ(out.hypotheses[0].x, 8.5);
  EXPECT_THROW(fusion.update(fusion::TickEvidence{}), std::invalid_argument);
}

TEST(Fusion, RestoredHypothesesKeepTheirVerdictsUntilNewEvidence) {
  const std::vector<scene_object_t> objects = {
      test::sounding(test::boxObject("radio", "siren", 12, 6, 0, 0.4, 0.3, 0.3), "playing", "person"),
      test::sounding(test::cylinderObject("victim", "person", 3, 3, 0.3, 1.8), "yelling")};
  fusion::HypothesisFusion before;
  before.update(Tick(objects, 0).seen("radio", "siren", 0, 0.0).heard("radio", "person", 0.6, 12, 6).evidence());
  before.update(Tick(objects, 1).seen("radio", "siren", 80, 0.9).evidence());
  before.update(Tick(objects, 2).heard("victim", "person", 0.4, 3.2, 2.9, false).evidence());
  const hypotheses_t published = before.hypotheses(200000, 2);
  ASSERT_EQ(published.num_hypotheses, 2);

  // A restarted fusion with nothing new: the same hypotheses.
  fusion::HypothesisFusion after;
  after.restore(published);
  after.update(Tick(objects, 3).evidence());
  const hypotheses_t resumed = after.hypotheses(300000, 3);
  ASSERT_EQ(resumed.num_hypotheses, 2);
  for (int i = 0; i < 2; ++i) {
    const auto& p = published.hypotheses[i];
    const auto& r = resumed.hypotheses[i];
    EXPECT_EQ(r.object_id, p.object_id);
    EXPECT_EQ(r.seen, p.seen);
    EXPECT_EQ(r.heard, p.heard);
    EXPECT_EQ(r.seen_as, p.seen_as);
    EXPECT_EQ(r.heard_as, p.heard_as);
    EXPECT_EQ(r.verified, p.verified);
    EXPECT_EQ(r.falsified, p.falsified);
    EXPECT_EQ(r.settled_utime, p.settled_utime);
    EXPECT_EQ(r.first_heard_utime, p.first_heard_utime);
    EXPECT_DOUBLE_EQ(r.x, p.x);
    EXPECT_DOUBLE_EQ(r.y, p.y);
    EXPECT_EQ(r.located, p.located);
    EXPECT_EQ(r.fused, p.fused);
    EXPECT_EQ(r.best_category, p.best_category);
  }
  EXPECT_TRUE(find(resumed, "radio")->falsified);

  // New acoustic evidence: the radio stays falsified; its published fused
  // confidences stand in for the visual side it has not seen again.
  after.update(Tick(objects, 4).heard("radio", "person", 0.5, 12, 6).evidence());
  const hypotheses_t latest = after.hypotheses(400000, 4);  // find() points into it
  const hypothesis_t* radio = find(latest, "radio");
  ASSERT_NE(radio, nullptr);
  EXPECT_TRUE(radio->falsified);
  EXPECT_EQ(radio->seen_as, "siren");
  EXPECT_EQ(radio->heard_as, "person");
  const auto* previous = find(published, "radio");
  const auto acoustic = model::labelConfidences(kCategories, "person", 0.5);
  EXPECT_NEAR(fusedOf(*radio, "siren"),
              (0.5 * acoustic[2] + previous->confidence * fusedOf(*previous, "siren")) / (0.5 + previous->confidence),
              1e-12);

  // Restoring into a fusion that already holds hypotheses changes nothing.
  hypotheses_t other = published;
  other.hypotheses[0].object_id = "ghost";
  after.restore(other);
  EXPECT_EQ(find(after.hypotheses(400000, 4), "ghost"), nullptr);
}

// Hypotheses are found again by id and new ones take the scenario's order,
// also when the scene's objects change between ticks (one added, the list
// reordered, one moved): what is seen is placed where the scene of its tick
// has it.
TEST(Fusion, FollowsTheSceneOfEachTickWhenItsObjectsChange) {
  const auto crate = [](double x) { return test::boxObject("crate", "car", x, 2, 0, 1, 1, 1); };
  const scene_object_t victim = test::cylinderObject("victim", "person", 10, 5, 0.3, 1.8);
  const scene_object_t siren = test::sounding(test::boxObject("siren", "siren", 4, -3, 0, 0.5, 0.5, 1), "siren");
  fusion::HypothesisFusion fusion;
  fusion.update(Tick({victim, crate(3)}, 0).seen("crate", "car", 80, 0.9).evidence());
  // The crate moved and comes first now; a siren appeared between them.
  fusion.update(Tick({crate(6), siren, victim}, 1)
                    .seen("victim", "person", 80, 0.9)
                    .seen("crate", "car", 80, 0.9)
                    .heard("siren", "siren", 0.5, 4.2, -3.1)
                    .evidence());
  const hypotheses_t out = fusion.hypotheses(100000, 1);
  ASSERT_EQ(out.num_hypotheses, 3);
  EXPECT_EQ(out.hypotheses[0].object_id, "crate");  // first perceived first
  EXPECT_EQ(out.hypotheses[1].object_id, "siren");  // then tick 1's new ones in scenario order
  EXPECT_EQ(out.hypotheses[2].object_id, "victim");
  EXPECT_DOUBLE_EQ(find(out, "crate")->x, 6);  // where tick 1's scene has it
  EXPECT_DOUBLE_EQ(find(out, "victim")->x, 10);
  EXPECT_DOUBLE_EQ(find(out, "siren")->x, 4.2);  // heard only: the acoustic estimate
}

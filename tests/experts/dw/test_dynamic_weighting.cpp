// Dynamic weighting (eq. 4, spec/model.md): the numbers of the spec, step by step.
#include <gtest/gtest.h>

#include <cmath>

#include "experts/dw/dynamic_weighting.hpp"

namespace beft::dw {
namespace {

Stimulus heard(const std::string& id, const std::string& label, const std::string& activity) {
  Stimulus s;
  s.object_id = id;
  s.label = label;
  s.activity = activity;
  s.x = 4;
  s.y = 2;
  return s;
}

// Steps n times with the same stimuli; returns every reflex trigger seen.
std::vector<ReflexTrigger> stepTimes(DynamicWeighting& dw, int n, const std::vector<Stimulus>& s) {
  std::vector<ReflexTrigger> all;
  for (int i = 0; i < n; ++i)
    for (auto& t : dw.step(s)) all.push_back(t);
  return all;
}

double weightOf(const DynamicWeighting& dw, const std::string& id) {
  const ObjectWeight* o = dw.find(id);
  EXPECT_NE(o, nullptr) << id;
  return o ? o->weight : NAN;
}

TEST(DynamicWeighting, NewObjectStartsAtOneHalf) {
  DynamicWeighting dw;
  auto triggers = dw.step({heard("walker", "person", "walking")});
  EXPECT_TRUE(triggers.empty());
  ASSERT_EQ(dw.objects().size(), 1u);
  EXPECT_DOUBLE_EQ(dw.objects()[0].weight, 0.5);
  EXPECT_DOUBLE_EQ(dw.objects()[0].congruency, 0.25);
  EXPECT_EQ(dw.objects()[0].step, 0);
  EXPECT_TRUE(dw.objects()[0].sounding);
}

TEST(DynamicWeighting, WalkingPersonFallsFromQuarterToZeroInTmaxSteps) {
  DynamicWeighting dw;
  const auto walking = std::vector<Stimulus>{heard("walker", "person", "walking")};
  dw.step(walking);  // new: 0.5
  dw.step(walking);  // t = 1: w = c = 0.25
  EXPECT_DOUBLE_EQ(weightOf(dw, "walker"), 0.25);
  EXPECT_FALSE(dw.find("walker")->rising);
  dw.step(walking);  // t = 2: 0.25 - log(2) / (2 log 100)
  EXPECT_NEAR(weightOf(dw, "walker"), 0.25 - std::log(2.0) / (2 * std::log(100.0)), 1e-12);
  stepTimes(dw, 8, walking);  // t = 10 = T_max
  EXPECT_EQ(dw.find("walker")->step, 10);
  EXPECT_NEAR(weightOf(dw, "walker"), 0.0, 1e-12);
}

// The paper's example: a walking person starts yelling, then stops.
TEST(DynamicWeighting, YellingJumpsToThreeQuartersRisesToOneThenFallsToOneHalf) {
  DynamicWeighting dw;
  const auto walking = std::vector<Stimulus>{heard("walker", "person", "walking")};
  const auto yelling = std::vector<Stimulus>{heard("walker", "person", "yelling")};
  stepTimes(dw, 12, walking);
  ASSERT_NEAR(weightOf(dw, "walker"), 0.0, 1e-12);

  auto triggers = dw.step(yelling);  // jump: new rising curve at t = 1
  EXPECT_DOUBLE_EQ(weightOf(dw, "walker"), 0.75);
  EXPECT_DOUBLE_EQ(dw.find("walker")->congruency, 0.75);
  EXPECT_TRUE(dw.find("walker")->rising);
  ASSERT_EQ(triggers.size(), 1u);
  EXPECT_EQ(triggers[0].object_id, "walker");
  EXPECT_DOUBLE_EQ(triggers[0].weight_before, 0.0);
  EXPECT_DOUBLE_EQ(triggers[0].weight_after, 0.75);

  // Rising: below 0.99 at t = 9, 1.0 at t = T_max = 10 (T_max steps of yelling).
  auto more = stepTimes(dw, 8, yelling);  // t = 9
  EXPECT_NEAR(weightOf(dw, "walker"), 0.75 + std::log(9.0) / (2 * std::log(100.0)), 1e-12);
  EXPECT_LT(weightOf(dw, "walker"), 0.99);
  more = stepTimes(dw, 1, yelling);  // t = 10
  EXPECT_GE(weightOf(dw, "walker"), 0.99);
  EXPECT_NEAR(weightOf(dw, "walker"), 1.0, 1e-12);
  EXPECT_TRUE(more.empty()) << "the reflex fires once, at the crossing";

  // Stops yelling: c stays 0.75, the curve falls from it to 0.5 within T_max steps.
  dw.step(walking);
  EXPECT_DOUBLE_EQ(weightOf(dw, "walker"), 0.75);
  EXPECT_DOUBLE_EQ(dw.find("walker")->congruency, 0.75);
  EXPECT_FALSE(dw.find("walker")->rising);
  stepTimes(dw, 9, walking);  // t = 10
  EXPECT_NEAR(weightOf(dw, "walker"), 0.5, 0.01);
  EXPECT_NEAR(weightOf(dw, "walker"), 0.5, 1e-12);
}

TEST(DynamicWeighting, ReflexFiresOnceAtTheUpwardCrossingOfANewIncongruentObject) {
  DynamicWeighting dw;
  const auto yelling = std::vector<Stimulus>{heard("victim", "person", "yelling")};
  EXPECT_TRUE(dw.step(yelling).empty());  // new: 0.5
  auto triggers = dw.step(yelling);       // t = 1: 0.75
  ASSERT_EQ(triggers.size(), 1u);
  EXPECT_EQ(triggers[0].object_id, "victim");
  EXPECT_DOUBLE_EQ(triggers[0].x, 4);
  EXPECT_DOUBLE_EQ(triggers[0].y, 2);
  EXPECT_TRUE(stepTimes(dw, 30, yelling).empty());
  EXPECT_DOUBLE_EQ(weightOf(dw, "victim"), 1.0);
}

TEST(DynamicWeighting, CongruentObjectsNovelSoundFallsAndDoesNotTriggerTheReflex) {
  DynamicWeighting dw;
  // A new congruent object: 0.5, then 0.25 falling to 0; no reflex.
  const auto idle = std::vector<Stimulus>{heard("car", "car", "idle")};
  EXPECT_TRUE(stepTimes(dw, 3, idle).empty());
  EXPECT_LT(weightOf(dw, "car"), 0.25);
  // Silent for a while, then a novel but still congruent sound: keeps falling.
  stepTimes(dw, 5, {});
  const double before = weightOf(dw, "car");
  const auto walking = std::vector<Stimulus>{heard("car", "person", "walking")};  // c = 0.25 too
  EXPECT_TRUE(stepTimes(dw, 10, walking).empty());
  EXPECT_LT(weightOf(dw, "car"), before);
  EXPECT_NEAR(weightOf(dw, "car"), 0.0, 1e-12);
}

TEST(DynamicWeighting, BurningFireFallsThenRisesWhenItSpreads) {
  DynamicWeighting dw;
  const auto burning = std::vector<Stimulus>{heard("fire", "fire", "burning")};
  const auto spreading = std::vector<Stimulus>{heard("fire", "fire", "spreading")};
  dw.step(burning);  // new: 0.5
  dw.step(burning);  // t = 1: c = 0.5, falling
  EXPECT_DOUBLE_EQ(weightOf(dw, "fire"), 0.5);
  stepTimes(dw, 9, burning);  // t = 10
  EXPECT_NEAR(weightOf(dw, "fire"), 0.25, 1e-12);

  auto triggers = dw.step(spreading);
  EXPECT_DOUBLE_EQ(weightOf(dw, "fire"), 0.75);
  EXPECT_TRUE(dw.find("fire")->rising);
  ASSERT_EQ(triggers.size(), 1u);
  double previous = weightOf(dw, "fire");
  for (int t = 2; t <= 10; ++t) {
    dw.step(spreading);
    EXPECT_GT(weightOf(dw, "fire"), previous) << "t = " << t;
    previous = weightOf(dw, "fire");
  }
  EXPECT_NEAR(previous, 1.0, 1e-12);
}

TEST(DynamicWeighting, ASilentObjectThatWasNeverIncongruentKeepsItsWeightAndCurve) {
  DynamicWeighting dw;
  const auto burning = std::vector<Stimulus>{heard("fire", "fire", "burning")};
  stepTimes(dw, 4, burning);  // t = 3 on the falling curve of c = 0.5
  const ObjectWeight before = *dw.find("fire");
  stepTimes(dw, 20, {});
  const ObjectWeight* after = dw.find("fire");
  EXPECT_FALSE(after->sounding);
  EXPECT_DOUBLE_EQ(after->weight, before.weight);
  EXPECT_EQ(after->step, before.step);
  dw.step(burning);  // continues the same curve at t = 4
  EXPECT_EQ(dw.find("fire")->step, 4);
  EXPECT_NEAR(weightOf(dw, "fire"), 0.5 - std::log(4.0) / (2 * std::log(100.0)), 1e-12);
}

// spec/model.md: "the incongruent stimulus stops (... or silence)": a falling
// curve with c kept at 0.75 to the residual 0.5, and it stays there.
TEST(DynamicWeighting, AYellingPersonWhoFallsSilentFallsToTheResidualAndStays) {
  DynamicWeighting dw;
  const auto yelling = std::vector<Stimulus>{heard("victim", "person", "yelling")};
  stepTimes(dw, 11, yelling);  // new, then t = 1..10: 1.0
  ASSERT_NEAR(weightOf(dw, "victim"), 1.0, 1e-12);
  dw.step({});
  EXPECT_DOUBLE_EQ(weightOf(dw, "victim"), 0.75);
  EXPECT_FALSE(dw.find("victim")->rising);
  for (int t = 2; t <= 10; ++t) {
    dw.step({});
    EXPECT_NEAR(weightOf(dw, "victim"), 0.75 - std::log(t) / (2 * std::log(100.0)), 1e-12) << "t = " << t;
  }
  EXPECT_NEAR(weightOf(dw, "victim"), 0.5, 1e-12);
  stepTimes(dw, 50, {});
  EXPECT_NEAR(weightOf(dw, "victim"), 0.5, 1e-12);
}

TEST(DynamicWeighting, OnceIncongruentAnObjectNeverFallsBelowTheResidual) {
  DynamicWeighting dw;
  const auto yelling = std::vector<Stimulus>{heard("walker", "person", "yelling")};
  const auto walking = std::vector<Stimulus>{heard("walker", "person", "walking")};
  stepTimes(dw, 11, yelling);  // new, then t = 1..10: w = 1.0
  stepTimes(dw, 10, walking);  // c kept at 0.75, falls to 0.5 at t = 10
  ASSERT_NEAR(weightOf(dw, "walker"), 0.5, 1e-12);
  // Unchanged at 0.5 for T_max more steps: c is still the kept 0.75.
  stepTimes(dw, 10, walking);
  EXPECT_DOUBLE_EQ(dw.find("walker")->congruency, 0.75);
  EXPECT_EQ(dw.find("walker")->unchanged_steps, 10);
  // More than T_max unchanged: re-evaluated to walking's c = 0.25, a new
  // falling curve, held at the floor.
  dw.step(walking);
  EXPECT_DOUBLE_EQ(dw.find("walker")->congruency, 0.25);
  EXPECT_EQ(dw.find("walker")->step, 1);
  EXPECT_DOUBLE_EQ(weightOf(dw, "walker"), 0.5);
  stepTimes(dw, 40, walking);
  EXPECT_DOUBLE_EQ(weightOf(dw, "walker"), 0.5);
  // Yelling again jumps to 0.75 and fires the reflex again.
  const auto triggers = dw.step(yelling);
  EXPECT_DOUBLE_EQ(weightOf(dw, "walker"), 0.75);
  ASSERT_EQ(triggers.size(), 1u);
  EXPECT_DOUBLE_EQ(triggers[0].weight_before, 0.5);
}

TEST(DynamicWeighting, ANovelCongruentSoundNeverJumpsUp) {
  DynamicWeighting dw;
  const auto idle = std::vector<Stimulus>{heard("car", "car", "idle")};           // c = 0.25
  const auto ringing = std::vector<Stimulus>{heard("car", "siren", "ringing")};   // c = 0.5
  stepTimes(dw, 3, idle);  // 0.5, then 0.25, then falling
  const double before = weightOf(dw, "car");
  ASSERT_LT(before, 0.25);
  const auto triggers = stepTimes(dw, 1, ringing);
  EXPECT_TRUE(triggers.empty());
  EXPECT_DOUBLE_EQ(dw.find("car")->congruency, 0.5);
  EXPECT_FALSE(dw.find("car")->rising);
  EXPECT_DOUBLE_EQ(weightOf(dw, "car"), before) << "a falling curve from 0.5 may not lift the weight";
  // The new curve (0.5 down to 0.25) stays above the weight: it never lifts it.
  stepTimes(dw, 20, ringing);
  EXPECT_DOUBLE_EQ(weightOf(dw, "car"), before);
  // A novel pair whose curve lies lower takes the weight down at once.
  stepTimes(dw, 1, {heard("car", "person", "walking")});  // c = 0.25: its curve starts at 0.25
  EXPECT_DOUBLE_EQ(weightOf(dw, "car"), before);
  stepTimes(dw, 9, {heard("car", "person", "walking")});
  EXPECT_NEAR(weightOf(dw, "car"), 0.0, 1e-12);
}

TEST(DynamicWeighting, ReevaluationKeepsASaturatedCurveWhoseCongruencyIsUnchanged) {
  DynamicWeighting dw;
  const auto yelling = std::vector<Stimulus>{heard("victim", "person", "yelling")};
  stepTimes(dw, 40, yelling);
  EXPECT_DOUBLE_EQ(weightOf(dw, "victim"), 1.0);
  EXPECT_DOUBLE_EQ(dw.find("victim")->congruency, 0.75);
}

TEST(DynamicWeighting, ReevaluationCanBeSwitchedOff) {
  DwParameters p;
  p.reevaluate = false;
  DynamicWeighting dw(p);
  stepTimes(dw, 11, {heard("walker", "person", "yelling")});
  stepTimes(dw, 40, {heard("walker", "person", "walking")});
  EXPECT_NEAR(weightOf(dw, "walker"), 0.5, 1e-12);
}

TEST(DynamicWeighting, ScenarioTableAndUnknownPairs) {
  CongruencyTable table;
  table.clear();
  table.set("siren", "ringing", 0.75);
  DynamicWeighting dw({}, table);
  dw.step({heard("radio", "siren", "ringing"), heard("thing", "car", "honking")});
  auto triggers = dw.step({heard("radio", "siren", "ringing"), heard("thing", "car", "honking")});
  ASSERT_EQ(triggers.size(), 1u);
  EXPECT_EQ(triggers[0].object_id, "radio");
  EXPECT_DOUBLE_EQ(dw.find("thing")->congruency, 0.5);  // not in the table: default
  EXPECT_THROW(table.set("fire", "burning", 1.5), std::invalid_argument);
}

TEST(DynamicWeighting, TriggersComeInFirstHeardOrder) {
  DynamicWeighting dw;
  dw.step({heard("a", "fire", "spreading"), heard("b", "person", "yelling")});
  auto triggers = dw.step({heard("b", "person", "yelling"), heard("a", "fire", "spreading")});
  ASSERT_EQ(triggers.size(), 2u);
  EXPECT_EQ(triggers[0].object_id, "a");
  EXPECT_EQ(triggers[1].object_id, "b");
  ASSERT_EQ(dw.objects().size(), 2u);
  EXPECT_EQ(dw.objects()[0].object_id, "a");
}

Stimulus at(const std::string& id, const std::string& label, const std::string& activity, double x, double y) {
  Stimulus s = heard(id, label, activity);
  s.x = x;
  s.y = y;
  return s;
}

TEST(DynamicWeighting, APersonNearASpreadingFireIsEndangered) {
  DynamicWeighting dw;
  // A walking person 5 m from a burning fire: congruent, falling.
  stepTimes(dw, 3, {at("walker", "person", "walking", 0, 0), at("fire", "fire", "burning", 5, 0)});
  ASSERT_LT(weightOf(dw, "walker"), 0.25);
  // The fire spreads: a hazard, but 5 m is beyond the 3 m radius.
  auto triggers = dw.step({at("walker", "person", "walking", 0, 0), at("fire", "fire", "spreading", 5, 0)});
  EXPECT_FALSE(dw.find("walker")->endangered);
  ASSERT_EQ(triggers.size(), 1u);
  EXPECT_EQ(triggers[0].object_id, "fire");
  // The walker comes within 3 m: endangered, c = 0.75 whatever it does.
  triggers = dw.step({at("walker", "person", "walking", 2.5, 0), at("fire", "fire", "spreading", 5, 0)});
  EXPECT_TRUE(dw.find("walker")->endangered);
  EXPECT_DOUBLE_EQ(weightOf(dw, "walker"), 0.75);
  EXPECT_TRUE(dw.find("walker")->rising);
  ASSERT_EQ(triggers.size(), 1u);
  EXPECT_EQ(triggers[0].object_id, "walker");
  // Away again: the danger is over, it falls with c kept to the residual.
  dw.step({at("walker", "person", "walking", -2, 0), at("fire", "fire", "spreading", 5, 0)});
  EXPECT_FALSE(dw.find("walker")->endangered);
  EXPECT_FALSE(dw.find("walker")->rising);
  stepTimes(dw, 30, {at("walker", "person", "walking", -2, 0), at("fire", "fire", "spreading", 5, 0)});
  EXPECT_DOUBLE_EQ(weightOf(dw, "walker"), 0.5);
  // A burning (harmless) fire endangers nobody; radius 0 turns danger off.
  DwParameters off;
  off.danger_radius = 0;
  DynamicWeighting no_danger(off);
  stepTimes(no_danger, 3, {at("w", "person", "walking", 0, 0), at("f", "fire", "spreading", 1, 0)});
  EXPECT_FALSE(no_danger.find("w")->endangered);
  EXPECT_LT(weightOf(no_danger, "w"), 0.25);
}

TEST(DynamicWeighting, StepIndexIsAFloorOfSimulatedTime) {
  EXPECT_EQ(stepIndex(0, 500000), 0);
  EXPECT_EQ(stepIndex(499999, 500000), 0);
  EXPECT_EQ(stepIndex(500000, 500000), 1);
  EXPECT_EQ(stepIndex(-1, 500000), -1);
  EXPECT_THROW(stepIndex(0, 0), std::invalid_argument);
}

}  // namespace
}  // namespace beft::dw

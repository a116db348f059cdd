// The dynamic-weighting expert class without LCM: what it waits for, when it
// steps, the estimated label it uses, the scenario's congruency table, the
// reflex task it pushes and the DYNAMIC_WEIGHTS it publishes every tick.
#include <gtest/gtest.h>

#include <cmath>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/dynamic_weights_t.hpp>
#include <beft/labels_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/task_command_t.hpp>
#include <beft/task_stack_t.hpp>

#include "lib/common/channels.hpp"
#include "experts/dw/dw_expert.hpp"
#include "tests/experts/support/expert_harness.hpp"

namespace beft::dw {
namespace {

using testing_support::CollectingOutput;
using testing_support::deliver;
using testing_support::firing;

struct Heard {
  std::string id, acoustic_label, activity;
  std::string best_label;  // what LABELS_ACOUSTIC makes most likely, empty: no entry
};

class DwExpertTest : public ::testing::Test {
 protected:
  void SetUp() override {
    expert::Parameters p;
    expert_.startUp(p);
  }

  // Everything of one tick except what a test leaves out.
  void feed(int64_t tick, const std::vector<Heard>& heard, bool audio = true, bool labels = true) {
    const int64_t utime = tick * 100000;
    scene_objects_t scene{};
    scene.utime = utime;
    scene.tick = tick;
    scene.congruency = congruency_;
    scene.num_congruency = static_cast<int32_t>(scene.congruency.size());
    scene.num_categories = 0;
    scene.num_objects = 0;
    ASSERT_TRUE(deliver(expert_, channels::kGroundTruth, scene));
    robot_state_t robot{};
    robot.utime = utime;
    robot.tick = tick;
    robot.yaw = 170;
    robot.head_yaw = 30;
    ASSERT_TRUE(deliver(expert_, channels::kRobotState, robot));
    acoustic_percepts_t percepts{};
    percepts.utime = utime;
    percepts.tick = tick;
    labels_t estimates{};
    estimates.utime = utime;
    estimates.tick = tick;
    estimates.modality = labels_t::MODALITY_ACOUSTIC;
    for (const auto& h : heard) {
      acoustic_percept_t p{};
      p.object_id = h.id;
      p.acoustic_label = h.acoustic_label;
      p.activity = h.activity;
      p.est_x = 3;
      p.est_y = 4;
      percepts.percepts.push_back(p);
      if (h.best_label.empty()) continue;
      object_labels_t o{};
      o.object_id = h.id;
      o.perceptibility = 0.8;
      o.categories = {"person", "car", "siren", "wall", "fire"};
      for (const auto& c : o.categories) o.confidence.push_back(c == h.best_label ? 0.9 : 0.1);
      o.num_categories = 5;
      estimates.objects.push_back(o);
    }
    percepts.num_percepts = static_cast<int32_t>(percepts.percepts.size());
    estimates.num_objects = static_cast<int32_t>(estimates.objects.size());
    if (audio) {
      ASSERT_TRUE(deliver(expert_, channels::kAudio, percepts));
    }
    if (labels) {
      ASSERT_TRUE(deliver(expert_, channels::kLabelsAcoustic, estimates));
    }
  }

  void fireTick(int64_t tick) {
    const auto f = firing("dw", tick);
    ASSERT_TRUE(expert_.inputsReady(f)) << "tick " << tick;
    ASSERT_TRUE(expert_.fire(f, out_).ok) << "tick " << tick;
  }

  double lastWeight(const std::string& id) const {
    const auto all = out_.on<dynamic_weights_t>(channels::kDynamicWeights);
    if (all.empty()) return -1;
    for (const auto& w : all.back().weights)
      if (w.object_id == id) return w.weight;
    return -1;
  }

  DwExpert expert_;
  CollectingOutput out_;
  std::vector<congruency_entry_t> congruency_;
};

TEST_F(DwExpertTest, PublishesEveryTickAndStepsEveryHalfSecond) {
  const std::vector<Heard> walking{{"walker", "person", "walking", "person"}};
  std::vector<double> weights;
  for (int64_t tick = 0; tick <= 10; ++tick) {
    feed(tick, walking);
    fireTick(tick);
    weights.push_back(lastWeight("walker"));
  }
  const auto all = out_.on<dynamic_weights_t>(channels::kDynamicWeights);
  ASSERT_EQ(all.size(), 11u);
  EXPECT_EQ(all[3].tick, 3);
  // New at tick 0 (t = 0): 0.5 until the next step at tick 5 (t = 0.5 s): 0.25.
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(weights[i], 0.5) << i;
  for (int i = 5; i < 10; ++i) EXPECT_DOUBLE_EQ(weights[i], 0.25) << i;
  EXPECT_LT(weights[10], 0.25);
  // No weight at or above the reflex threshold: DW asks for no direction.
  EXPECT_TRUE(std::isnan(all.back().viewing_direction));
  EXPECT_EQ(all.back().weights[0].label, "person");
  EXPECT_EQ(all.back().weights[0].activity, "walking");
  EXPECT_TRUE(all.back().weights[0].sounding);
  EXPECT_TRUE(out_.on<task_command_t>(channels::kTaskCommand).empty());
}

TEST_F(DwExpertTest, WaitsForTheTicksAudioAndLabelsOnlyOnStepTicks) {
  feed(0, {}, false, false);
  EXPECT_FALSE(expert_.inputsReady(firing("dw", 0))) << "tick 0 is a step tick";
  feed(0, {});
  fireTick(0);
  feed(1, {}, false, false);
  EXPECT_TRUE(expert_.inputsReady(firing("dw", 1))) << "no step at t = 0.1 s";
  EXPECT_FALSE(expert_.inputsReady(firing("dw", 5))) << "no robot state yet for tick 5";
}

TEST_F(DwExpertTest, ReflexPushesALookAtOnceWhenAYellingVoiceIsHeard) {
  // A radio playing a voice: the labels say person, the activity is yelling.
  const std::vector<Heard> radio{{"radio", "siren", "yelling", "person"}};
  for (int64_t tick = 0; tick <= 30; ++tick) {
    feed(tick, radio);
    fireTick(tick);
  }
  const auto commands = out_.on<task_command_t>(channels::kTaskCommand);
  ASSERT_EQ(commands.size(), 1u);
  const auto& c = commands[0];
  EXPECT_EQ(c.command, task_command_t::COMMAND_PUSH);
  EXPECT_EQ(c.utime, 500000) << "the second step, at t = 0.5 s";
  EXPECT_EQ(c.task.kind, "look_at");
  EXPECT_EQ(c.task.object_id, "radio");
  EXPECT_EQ(c.task.priority, 100);
  EXPECT_EQ(c.task.origin, "dw");
  EXPECT_DOUBLE_EQ(c.task.x, 3);
  EXPECT_DOUBLE_EQ(c.task.y, 4);
  const auto last = out_.on<dynamic_weights_t>(channels::kDynamicWeights).back();
  EXPECT_EQ(last.attended_object, "radio");
  EXPECT_EQ(last.weights[0].label, "person") << "the estimated label, not the audio expert's";
  EXPECT_NEAR(last.weights[0].weight, 0.75 + std::log(6.0) / (2 * std::log(100.0)), 1e-12) << "t = 6 at 3.0 s";
}

TEST_F(DwExpertTest, UsesTheScenariosCongruencyTable) {
  congruency_entry_t entry{};
  entry.label = "siren";
  entry.activity = "ringing";
  entry.value = 0.75;
  congruency_.push_back(entry);
  const std::vector<Heard> siren{{"alarm", "siren", "ringing", "siren"}};
  for (int64_t tick = 0; tick <= 5; ++tick) {
    feed(tick, siren);
    fireTick(tick);
  }
  ASSERT_EQ(out_.on<task_command_t>(channels::kTaskCommand).size(), 1u);
  EXPECT_DOUBLE_EQ(lastWeight("alarm"), 0.75);
}

TEST_F(DwExpertTest, AnAmbiguousLabelFallsBackToTheAudioExpertsLabel) {
  const std::vector<Heard> far{{"car1", "car", "idle", ""}};  // no LABELS_ACOUSTIC entry
  for (int64_t tick = 0; tick <= 5; ++tick) {
    feed(tick, far);
    fireTick(tick);
  }
  const auto last = out_.on<dynamic_weights_t>(channels::kDynamicWeights).back();
  EXPECT_EQ(last.weights[0].label, "car");
  EXPECT_DOUBLE_EQ(last.weights[0].congruency, 0.25);
}

TEST_F(DwExpertTest, ShowsTheCurrentTask) {
  task_stack_t stack{};
  stack.utime = 0;
  stack.tick = 0;
  task_t task{};
  task.task_id = 3;
  task.kind = "goto";
  task.x = 12;
  task.y = 8;
  task.yaw = 90;
  stack.tasks.push_back(task);
  stack.num_tasks = 1;
  ASSERT_TRUE(deliver(expert_, channels::kTaskStack, stack));
  feed(1, {});
  fireTick(1);
  EXPECT_EQ(out_.on<dynamic_weights_t>(channels::kDynamicWeights).back().current_task, "goto(12, 8, 90)");
}

TEST(DwExpertParameters, RefusesBadValues) {
  DwExpert expert;
  expert::Parameters p;
  p["dw_step_s"] = "0";
  EXPECT_THROW(expert.startUp(p), std::invalid_argument);
  p["dw_step_s"] = "0.25";
  p["t_max"] = "0";
  EXPECT_THROW(expert.startUp(p), std::invalid_argument);
  p["t_max"] = "10";
  p["n"] = "abc";
  EXPECT_THROW(expert.startUp(p), std::invalid_argument);
  p["n"] = "100";
  EXPECT_NO_THROW(expert.startUp(p));
}

}  // namespace
}  // namespace beft::dw

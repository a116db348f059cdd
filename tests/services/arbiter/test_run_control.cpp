// Pause, step and run on (RUN_CONTROL) and the real-time pace, at the
// arbiter core on a scripted clock, with experts that answer every FIRE at
// once: where the run holds, what it answers, and that a held run fires
// exactly what a run that ran through fires.
#include <gtest/gtest.h>

#include <deque>
#include <set>
#include <string>
#include <vector>

#include "lib/petri/pnml_reader.hpp"
#include "services/arbiter/arbiter_core.hpp"

namespace beft::arbiter {
namespace {

using Mode = beft::run_control_t;
const std::string kDefaultNet = std::string(BEFT_SOURCE_DIR) + "/scenarios/nets/default.pnml";

class FakeClock : public Clock {
 public:
  double now() const override { return t; }
  double t = 0.0;
};

// The core with experts that each answer a FIRE 1 ms after it is sent.
class InstantRun : public ArbiterOutput {
 public:
  explicit InstantRun(int64_t ticks, Pace pace = Pace::kFast) : core_(readPnmlFile(kDefaultNet), config(ticks, pace), clock_, *this) {}

  void start() {
    core_.start();
    for (const auto& name : core_.net().experts()) core_.onHeartbeat(heartbeat(name));
  }
  // Answers every FIRE until none is left: the run ended, is held, or waits for its pace.
  void settle() {
    while (!unanswered_.empty()) {
      const beft::fire_t fire = unanswered_.front();
      unanswered_.pop_front();
      clock_.t += 0.001;
      beft::done_t done{};
      done.utime = fire.utime;
      done.expert = fire.expert;
      done.tick = fire.tick;
      done.firing_id = fire.firing_id;
      done.outcome = beft::done_t::OUTCOME_OK;
      core_.onDone(done);
    }
  }
  // Time passes with the experts alive (a heartbeat every 50 ms) and no FIRE answered.
  void idle(double seconds) {
    for (double until = clock_.t + seconds; clock_.t < until;) {
      clock_.t = std::min(until, clock_.t + 0.05);
      for (const auto& name : core_.net().experts()) core_.onHeartbeat(heartbeat(name));
      core_.onTimeAdvanced();
    }
  }
  void control(const std::string& origin, int64_t sequence, int8_t mode, int64_t hold_after_tick = 0) {
    beft::run_control_t request{};
    request.origin = origin;
    request.sequence = sequence;
    request.mode = mode;
    request.hold_after_tick = hold_after_tick;
    core_.onRunControl(request);
  }
  int64_t highestTickFired() const {
    int64_t highest = -1;
    for (const auto& fire : fires_) highest = std::max(highest, fire.tick);
    return highest;
  }

  ArbiterCore& core() { return core_; }
  FakeClock& clock() { return clock_; }
  const std::vector<beft::fire_t>& fires() const { return fires_; }
  const std::vector<beft::run_status_t>& statuses() const { return statuses_; }
  const std::vector<beft::run_control_t>& states() const { return states_; }

  void sendFire(const beft::fire_t& fire) override {
    if (!answered_.insert(fire.firing_id).second) return;  // a re-send
    fires_.push_back(fire);
    unanswered_.push_back(fire);
  }
  void sendMarking(const beft::marking_t& marking) override { last_marking_ = marking; }
  void sendRunStatus(const beft::run_status_t& status) override { statuses_.push_back(status); }
  void sendRunControlState(const beft::run_control_t& state) override { states_.push_back(state); }
  void firingEnded(const FiringRecord&) override {}

 private:
  static ArbiterConfig config(int64_t ticks, Pace pace) {
    ArbiterConfig config;
    config.max_ticks = ticks;
    config.dt_s = 0.1;
    config.heartbeat_timeout_s = 1.0;
    config.pace = pace;
    return config;
  }
  static beft::heartbeat_t heartbeat(const std::string& name) {
    beft::heartbeat_t beat{};
    beat.process = name;
    beat.state = "idle";
    return beat;
  }

  FakeClock clock_;
  ArbiterCore core_;
  std::set<int64_t> answered_;
  std::deque<beft::fire_t> unanswered_;
  std::vector<beft::fire_t> fires_;
  std::vector<beft::run_status_t> statuses_;
  std::vector<beft::run_control_t> states_;
  beft::marking_t last_marking_{};

 public:
  const beft::marking_t& lastMarking() const { return last_marking_; }
};

// What a FIRE says, for comparing two runs' firings.
std::vector<std::string> firingsOf(const std::vector<beft::fire_t>& fires) {
  std::vector<std::string> out;
  for (const auto& f : fires)
    out.push_back(f.expert + " " + f.transition + " tick " + std::to_string(f.tick) + " utime " +
                  std::to_string(f.utime) + " id " + std::to_string(f.firing_id));
  return out;
}

TEST(RunControl, APauseBeforeTheFirstTickHoldsAfterTickZeroAndEachStepRunsExactlyOneTick) {
  InstantRun run(10);
  run.control("user", 1, Mode::MODE_PAUSE);  // while the arbiter waits for heartbeats
  run.start();
  run.settle();
  ASSERT_TRUE(run.core().held());
  EXPECT_EQ(run.core().tick(), 0);
  EXPECT_EQ(run.highestTickFired(), 0);
  for (int64_t step = 1; step <= 3; ++step) {
    run.control("user", 1 + step, Mode::MODE_STEP, step);
    run.settle();
    ASSERT_TRUE(run.core().held()) << "step " << step;
    EXPECT_EQ(run.core().tick(), step);
    EXPECT_EQ(run.highestTickFired(), step);
    const beft::run_control_t state = run.states().back();
    EXPECT_EQ(state.mode, Mode::MODE_PAUSE);
    EXPECT_EQ(state.tick, step);
    EXPECT_EQ(state.origin, "user");
    EXPECT_EQ(state.sequence, 1 + step);
  }
  EXPECT_EQ(run.core().state(), RunState::Running);
}

TEST(RunControl, AHeldRunFiresNothingWhileTimePassesAndNoExpertTimesOut) {
  InstantRun run(10);
  run.start();
  run.control("viewer", 1, Mode::MODE_PAUSE);  // during tick 0
  run.settle();
  ASSERT_TRUE(run.core().held());
  const std::size_t fired = run.fires().size();
  run.idle(30.0);  // far beyond every timeout
  EXPECT_EQ(run.fires().size(), fired);
  EXPECT_EQ(run.core().state(), RunState::Running) << run.core().message();
  EXPECT_TRUE(run.core().held());
  EXPECT_EQ(run.core().tick(), 0);
  EXPECT_GE(run.states().size(), 100u) << "the state is repeated while held";
  EXPECT_EQ(run.states().back().mode, Mode::MODE_PAUSE);
}

TEST(RunControl, AHeldAndSteppedRunFiresExactlyWhatARunThatRanThroughFires) {
  InstantRun through(8);
  through.start();
  through.settle();
  ASSERT_EQ(through.core().state(), RunState::Finished);

  InstantRun held(8);
  held.start();
  held.control("user", 1, Mode::MODE_STEP, 2);
  held.settle();
  ASSERT_TRUE(held.core().held());
  EXPECT_EQ(held.core().tick(), 2);
  held.idle(5.0);
  held.control("user", 2, Mode::MODE_STEP, 3);
  held.settle();
  EXPECT_EQ(held.core().tick(), 3);
  held.control("user", 3, Mode::MODE_RUN);
  held.settle();
  ASSERT_EQ(held.core().state(), RunState::Finished) << held.core().message();
  EXPECT_EQ(held.core().message(), through.core().message());
  EXPECT_EQ(firingsOf(held.fires()), firingsOf(through.fires()));
}

TEST(RunControl, SaysInRunStatusThatTheRunIsPausedAtItsTick) {
  InstantRun run(10);
  run.start();
  run.control("viewer", 1, Mode::MODE_STEP, 4);
  run.settle();
  ASSERT_TRUE(run.core().held());
  EXPECT_EQ(run.statuses().back().tick, 4);
  EXPECT_NE(run.statuses().back().message.find("held after tick 4"), std::string::npos) << run.statuses().back().message;
  run.control("viewer", 2, Mode::MODE_PAUSE);
  run.control("viewer", 3, Mode::MODE_STEP, 5);
  run.control("viewer", 4, Mode::MODE_PAUSE);  // during tick 5
  run.settle();
  EXPECT_NE(run.statuses().back().message.find("paused after tick 5"), std::string::npos) << run.statuses().back().message;
}

TEST(RunControl, ARequestIsAppliedOncePerOriginAndSequence) {
  InstantRun run(10);
  run.start();
  run.control("viewer", 5, Mode::MODE_PAUSE);
  run.settle();
  ASSERT_TRUE(run.core().held());
  run.control("viewer", 4, Mode::MODE_RUN);  // older
  run.control("viewer", 5, Mode::MODE_RUN);  // the same number again
  run.settle();
  EXPECT_TRUE(run.core().held());
  EXPECT_EQ(run.core().tick(), 0);
  // Answered with what was applied for that origin: the requester learns it was heard.
  EXPECT_EQ(run.states().back().origin, "viewer");
  EXPECT_EQ(run.states().back().sequence, 5);
  run.control("tool", 1, Mode::MODE_STEP, 1);  // another origin numbers on its own
  run.settle();
  EXPECT_EQ(run.core().tick(), 1);
  run.control("viewer", 5, Mode::MODE_PAUSE);  // resent after the tool's: answered for the viewer
  EXPECT_EQ(run.states().back().origin, "viewer");
  EXPECT_EQ(run.states().back().sequence, 5);
  EXPECT_EQ(run.core().controlState().origin, "tool");
}

TEST(RunControl, RefusesAnInvalidRequestAndGoesOn) {
  InstantRun run(6);
  run.start();
  run.control("viewer", 1, 7);  // an unknown mode
  run.control("viewer", 2, Mode::MODE_STEP, -3);
  run.control("", 3, Mode::MODE_PAUSE);
  run.control("viewer", -1, Mode::MODE_PAUSE);
  run.control(std::string(200, 'x'), 1, Mode::MODE_PAUSE);
  run.settle();
  EXPECT_EQ(run.core().state(), RunState::Finished) << "nothing was applied";
  EXPECT_EQ(run.core().controlState().origin, "");
}

TEST(RunControl, AStopRequestWhileHeldEndsTheRunCleanly) {
  InstantRun run(50);
  run.start();
  run.control("user", 1, Mode::MODE_STEP, 3);
  run.settle();
  ASSERT_TRUE(run.core().held());
  run.core().onStopRequest("interrupted (SIGINT)");
  EXPECT_EQ(run.core().state(), RunState::Finished);
  EXPECT_EQ(run.core().message(), "stopped on request after 4 ticks: interrupted (SIGINT)");
  EXPECT_EQ(run.highestTickFired(), 3);
}

TEST(RunControl, ARestartedArbiterHoldsWhereTheRunWasHeld) {
  InstantRun through(8);
  through.start();
  through.settle();

  InstantRun before(8);
  before.start();
  before.control("viewer", 3, Mode::MODE_STEP, 2);
  before.settle();
  ASSERT_TRUE(before.core().held());
  ResumePoint point;  // what the run's log holds when the arbiter dies here
  point.marking = before.lastMarking();
  point.control = before.states().back();
  for (const auto& fire : before.fires()) {
    point.newest_fire[fire.expert] = fire;
    point.done_firing_ids.insert(fire.firing_id);
    point.highest_firing_id = std::max(point.highest_firing_id, fire.firing_id);
  }
  InstantRun after(8);
  after.core().resume(point);
  after.settle();
  EXPECT_TRUE(after.core().held());
  EXPECT_EQ(after.core().tick(), 2);
  EXPECT_TRUE(after.fires().empty());
  after.control("viewer", 3, Mode::MODE_RUN);  // its number was applied before the restart
  EXPECT_TRUE(after.core().held());
  after.control("viewer", 4, Mode::MODE_RUN);
  after.settle();
  ASSERT_EQ(after.core().state(), RunState::Finished) << after.core().message();
  std::vector<beft::fire_t> both = before.fires();
  both.insert(both.end(), after.fires().begin(), after.fires().end());
  EXPECT_EQ(firingsOf(both), firingsOf(through.fires()));
}

TEST(RunControl, ARealTimeTickStartsWhenItsSimulatedTimeHasPassedSinceTheRunOrItsResumeBegan) {
  InstantRun run(20, Pace::kRealTime);
  run.start();  // tick 0 starts at t = 0
  run.settle();
  EXPECT_EQ(run.highestTickFired(), 0);
  EXPECT_NEAR(run.core().nextDeadline(), 0.1, 1e-9);
  run.clock().t = 0.1;
  run.core().onTimeAdvanced();
  run.settle();
  EXPECT_EQ(run.highestTickFired(), 1);
  run.control("user", 1, Mode::MODE_PAUSE);
  run.settle();
  run.idle(0.5);  // held, however long
  ASSERT_TRUE(run.core().held());
  EXPECT_EQ(run.highestTickFired(), 1);
  run.idle(2.0);
  run.control("user", 2, Mode::MODE_RUN);  // tick 2 starts now, tick 3 a tick later
  EXPECT_EQ(run.highestTickFired(), 2);
  const double resumed = run.clock().t;
  run.settle();
  EXPECT_EQ(run.highestTickFired(), 2);
  EXPECT_NEAR(run.core().nextDeadline(), resumed + 0.1, 1e-9);
  run.clock().t = resumed + 0.1;
  run.core().onTimeAdvanced();
  EXPECT_EQ(run.highestTickFired(), 3);
}

}  // namespace
}  // namespace beft::arbiter

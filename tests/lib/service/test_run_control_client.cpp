// RunControlClient: what it sends, when it sends it again, and which answer
// of the arbiter acknowledges it.
#include <gtest/gtest.h>

#include "lib/service/run_control_client.hpp"

namespace beft::service {
namespace {

using Mode = beft::run_control_t;

beft::run_control_t answer(const std::string& origin, int64_t sequence, int8_t mode, int64_t tick,
                           int64_t hold_after_tick = 0) {
  beft::run_control_t state{};
  state.origin = origin;
  state.sequence = sequence;
  state.mode = mode;
  state.tick = tick;
  state.hold_after_tick = hold_after_tick;
  return state;
}

TEST(RunControlClient, SendsNothingBeforeARequest) {
  RunControlClient client("viewer");
  EXPECT_TRUE(client.acknowledged());
  EXPECT_FALSE(client.lastState().has_value());
  EXPECT_FALSE(client.due(0).has_value());
}

TEST(RunControlClient, SendsTheRequestAtOnceThenAgainEachIntervalUntilAnswered) {
  RunControlClient client("viewer");
  client.request(Mode::MODE_PAUSE, 0);
  EXPECT_FALSE(client.acknowledged());
  const auto first = client.due(1000);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->mode, Mode::MODE_PAUSE);
  EXPECT_EQ(first->origin, "viewer");
  EXPECT_EQ(first->utime, 1000);
  EXPECT_FALSE(client.due(1000 + RunControlClient::kResendInterval_us - 1).has_value());
  const auto again = client.due(1000 + RunControlClient::kResendInterval_us);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(again->sequence, first->sequence) << "a resend is the same request";
  client.onState(answer("viewer", first->sequence, Mode::MODE_STEP, 4, 4));
  EXPECT_TRUE(client.acknowledged());
  EXPECT_FALSE(client.due(10'000'000).has_value());
  ASSERT_TRUE(client.lastState().has_value());
  EXPECT_EQ(client.lastState()->tick, 4);
}

TEST(RunControlClient, EachRequestHasTheNextSequenceAndOnlyItsOwnAnswerAcknowledgesIt) {
  RunControlClient client("viewer", 7);
  client.request(Mode::MODE_PAUSE, 0);
  const int64_t pause = client.due(0)->sequence;
  client.request(Mode::MODE_RUN, 0);
  const int64_t run = client.due(0)->sequence;
  EXPECT_EQ(pause, 7);
  EXPECT_EQ(run, 8);
  client.onState(answer("viewer", pause, Mode::MODE_PAUSE, 3));
  EXPECT_FALSE(client.acknowledged()) << "the answer to the pause does not acknowledge the run";
  client.onState(answer("tool", run, Mode::MODE_RUN, 3));
  EXPECT_FALSE(client.acknowledged()) << "another origin's sequence";
  client.onState(answer("viewer", run, Mode::MODE_RUN, 3));
  EXPECT_TRUE(client.acknowledged());
}

TEST(RunControlClient, ARequestNumberedBelowWhatTheArbiterAppliedIsRenumberedAndSentAtOnce) {
  RunControlClient client("user");  // started again: numbers from 1, the arbiter applied 40 of "user"
  client.request(Mode::MODE_RUN, 0);
  ASSERT_TRUE(client.due(0).has_value());
  client.onState(answer("user", 40, Mode::MODE_PAUSE, 9));
  EXPECT_FALSE(client.acknowledged());
  const auto renumbered = client.due(1);  // not waiting for the interval
  ASSERT_TRUE(renumbered.has_value());
  EXPECT_EQ(renumbered->sequence, 41);
  EXPECT_EQ(renumbered->mode, Mode::MODE_RUN);
  client.onState(answer("user", 41, Mode::MODE_RUN, 9));
  EXPECT_TRUE(client.acknowledged());
  client.request(Mode::MODE_PAUSE, 0);
  EXPECT_EQ(client.due(2)->sequence, 42);
}

TEST(RunControlClient, StepOneHoldsAfterTheTickAfterTheLastKnown) {
  RunControlClient client("viewer");
  client.stepOne();
  EXPECT_EQ(client.due(0)->hold_after_tick, 0) << "nothing known: the first tick";
  client.onState(answer("viewer", client.desired()->sequence, Mode::MODE_PAUSE, 12));
  client.stepOne();
  const auto step = client.due(1);
  ASSERT_TRUE(step.has_value());
  EXPECT_EQ(step->mode, Mode::MODE_STEP);
  EXPECT_EQ(step->hold_after_tick, 13);
}

TEST(RunControlClient, StepOnePressedTwiceBeforeTheFirstStepIsReachedStepsTwice) {
  RunControlClient client("viewer");
  client.request(Mode::MODE_PAUSE, 0);
  client.onState(answer("viewer", client.desired()->sequence, Mode::MODE_PAUSE, 5));
  client.stepOne();  // unanswered yet
  client.stepOne();
  EXPECT_EQ(client.desired()->hold_after_tick, 7);
  client.onState(answer("viewer", client.desired()->sequence, Mode::MODE_STEP, 6, 7));
  client.stepOne();  // answered, still running towards 7
  EXPECT_EQ(client.desired()->hold_after_tick, 8);
  client.onState(answer("viewer", client.desired()->sequence, Mode::MODE_PAUSE, 8));
  client.stepOne();
  EXPECT_EQ(client.desired()->hold_after_tick, 9);
}

TEST(RunControlClient, DescribesTheArbitersState) {
  EXPECT_EQ(describeRunControlState(answer("", 0, Mode::MODE_PAUSE, 12)), "paused after tick 12");
  EXPECT_EQ(describeRunControlState(answer("", 0, Mode::MODE_STEP, 13, 15)), "stepping: holds after tick 15 (at tick 13)");
  EXPECT_EQ(describeRunControlState(answer("", 0, Mode::MODE_RUN, 40)), "running (at tick 40)");
  EXPECT_STREQ(runControlModeName(Mode::MODE_STEP), "step");
  EXPECT_STREQ(runControlModeName(9), "unknown");
}

}  // namespace
}  // namespace beft::service

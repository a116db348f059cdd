// The receiver's side of loss repair, message by message with the time
// passed in: gaps asked for at once and again after a back-off, messages
// handed on in order and once, gaps given up only when the sender says so or
// falls silent.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "lib/transport/detail/stream_tracker.hpp"

using beft::transport::Message;
using beft::transport::detail::StreamTracker;

namespace {

constexpr uint64_t kSender = 0xabcdef;
const std::string kChannel = "VISION@1f";

class Tracker : public ::testing::Test {
 protected:
  StreamTracker tracker{[](std::string_view channel) { return channel == kChannel; }};
  std::vector<std::string> handed;
  beft::transport::Handler deliver = [this](const Message& message) {
    handed.emplace_back(reinterpret_cast<const char*>(message.data), message.size);
  };

  void receive(uint64_t sequence, int64_t now_us, uint64_t sender = kSender, int64_t stream_start_us = 0) {
    const std::string payload = "m" + std::to_string(sequence);
    Message message;
    message.channel = kChannel;
    message.data = reinterpret_cast<const uint8_t*>(payload.data());
    message.size = payload.size();
    beft::wire::Envelope envelope;
    envelope.sender = sender;
    envelope.sequence = sequence;
    envelope.stream_start_us = stream_start_us;
    tracker.accept(message, envelope, now_us, deliver);
  }

  beft::sender_state_t state(int64_t last, int64_t first_kept) {
    beft::sender_state_t state;
    state.sender = static_cast<int64_t>(kSender);
    state.channels = {kChannel};
    state.last_sequences = {last};
    state.first_kept = {first_kept};
    state.stream_started = {0};
    state.count = 1;
    return state;
  }
};

TEST_F(Tracker, HandsOnAStreamInOrderAndOnce) {
  for (uint64_t sequence = 1; sequence <= 3; ++sequence) receive(sequence, 1000);
  receive(2, 1100);  // a copy (a repair someone else asked for)
  EXPECT_EQ(handed, (std::vector<std::string>{"m1", "m2", "m3"}));
  EXPECT_EQ(tracker.stats().duplicates, 1u);
  EXPECT_EQ(tracker.stats().gaps, 0u);
}

TEST_F(Tracker, AsksForAGapAtOnceAndHoldsWhatFollows) {
  receive(1, 1000);
  receive(3, 2000);
  receive(4, 2100);
  EXPECT_EQ(handed, (std::vector<std::string>{"m1"}));
  auto requests = tracker.due(2100, deliver);
  ASSERT_EQ(requests.size(), 1u);
  EXPECT_EQ(requests[0].sender, static_cast<int64_t>(kSender));
  EXPECT_EQ(requests[0].channel, kChannel);
  EXPECT_EQ(requests[0].sequences, (std::vector<int64_t>{2}));
  EXPECT_EQ(requests[0].count, 1);
  receive(2, 2600);
  EXPECT_EQ(handed, (std::vector<std::string>{"m1", "m2", "m3", "m4"}));
  EXPECT_EQ(tracker.stats().repaired, 1u);
  EXPECT_TRUE(tracker.due(1'000'000, deliver).empty());
}

TEST_F(Tracker, AsksAgainAfterABackOffThatGrowsAndKeepsAskingWhileTheSenderLives) {
  receive(1, 0);
  receive(3, 0);
  ASSERT_EQ(tracker.due(0, deliver).size(), 1u);
  EXPECT_TRUE(tracker.due(1000, deliver).empty()) << "asked again before the back-off";
  const int64_t second = tracker.nextDueUs();
  EXPECT_GE(second, 2000);
  ASSERT_EQ(tracker.due(second, deliver).size(), 1u);
  const int64_t third = tracker.nextDueUs();
  EXPECT_GT(third - second, second) << "the wait doubles";
  // The sender lives (its states come), so the gap is asked for long after.
  int64_t now = third;
  for (int i = 0; i < 40; ++i) {
    now += 200'000;
    tracker.onState(state(3, 1), now, deliver);
    tracker.due(now, deliver);
  }
  EXPECT_EQ(tracker.stats().lost, 0u);
  EXPECT_EQ(handed, (std::vector<std::string>{"m1"}));
  EXPECT_GT(tracker.stats().requests, 10u);
}

TEST_F(Tracker, LearnsOfALostLastMessageFromTheSendersState) {
  receive(1, 0);
  receive(2, 0);
  tracker.onState(state(3, 1), 5000, deliver);
  auto requests = tracker.due(5000, deliver);
  ASSERT_EQ(requests.size(), 1u);
  EXPECT_EQ(requests[0].sequences, (std::vector<int64_t>{3}));
  receive(3, 6000);
  EXPECT_EQ(handed.back(), "m3");
}

TEST_F(Tracker, GivesUpWhatTheSenderNoLongerKeepsAndHandsOnWhatFollows) {
  receive(1, 0);
  receive(4, 0);
  tracker.onState(state(4, 4), 1000, deliver);  // 2 and 3 are gone
  EXPECT_EQ(handed, (std::vector<std::string>{"m1", "m4"}));
  EXPECT_EQ(tracker.stats().lost, 2u);
  EXPECT_TRUE(tracker.due(2000, deliver).empty());
}

TEST_F(Tracker, GivesUpOnASenderThatFallsSilent) {
  receive(1, 0);
  receive(3, 0);
  tracker.due(0, deliver);
  EXPECT_TRUE(tracker.due(2'000'000, deliver).size() <= 1);
  EXPECT_EQ(handed.size(), 1u);
  tracker.due(3'500'000, deliver);  // not heard for more than 3 s: dead
  EXPECT_EQ(handed, (std::vector<std::string>{"m1", "m3"}));
  EXPECT_EQ(tracker.stats().lost, 1u);
}

TEST_F(Tracker, AStreamBegunAfterTheReceiverStartedIsTakenFromItsFirstMessage) {
  StreamTracker::Options options;
  options.listening_since_us = 1'000'000;
  StreamTracker late_starter([](std::string_view) { return true; }, options);
  tracker = std::move(late_starter);
  receive(3, 0, kSender, 2'000'000);  // 1 and 2 lost, the stream began after this receiver started
  EXPECT_TRUE(handed.empty());
  ASSERT_EQ(tracker.due(0, deliver).at(0).sequences, (std::vector<int64_t>{1, 2}));
  receive(1, 10, kSender, 2'000'000);
  receive(2, 20, kSender, 2'000'000);
  EXPECT_EQ(handed, (std::vector<std::string>{"m1", "m2", "m3"}));

  // A stream that began before: this receiver came late (a process restarted
  // mid-run); what came before is not its business.
  receive(5000, 30, kSender + 1, 500'000);
  EXPECT_EQ(handed.back(), "m5000");
  EXPECT_EQ(tracker.stats().joined_late, 1u);
  EXPECT_TRUE(tracker.due(40, deliver).empty());

  // Likewise through a state: only a stream begun after the start is asked for.
  beft::sender_state_t old_stream = state(9, 1);
  old_stream.sender = static_cast<int64_t>(kSender + 2);
  old_stream.stream_started = {500'000};
  tracker.onState(old_stream, 50, deliver);
  EXPECT_TRUE(tracker.due(50, deliver).empty());
  beft::sender_state_t new_stream = old_stream;
  new_stream.stream_started = {3'000'000};
  new_stream.sender = static_cast<int64_t>(kSender + 3);
  tracker.onState(new_stream, 60, deliver);
  ASSERT_EQ(tracker.due(60, deliver).size(), 1u);
}

TEST_F(Tracker, ALeavingSenderIsAskedOftenEnoughThatItStillAnswers) {
  receive(1, 0);
  beft::sender_state_t leaving = state(2, 1);
  leaving.leaving = true;
  leaving.process = "vision";
  tracker.onState(leaving, 0, deliver);
  int64_t now = 0, longest_wait = 0, asks = 0;
  while (now < 240'000) {  // within the time a leaving sender still answers (publisher.cpp: 250 ms quiet)
    const int64_t next = tracker.nextDueUs();
    longest_wait = std::max(longest_wait, next - now);
    now = next;
    tracker.onState(leaving, now, deliver);  // its states keep coming while it waits
    asks += static_cast<int64_t>(tracker.due(now, deliver).size());
  }
  EXPECT_LE(longest_wait, 25'000) << "a leaving sender waits 250 ms for the next ask at most";
  EXPECT_GE(asks, 9);
  EXPECT_EQ(tracker.stats().lost, 0u);
}

TEST_F(Tracker, NamesWhatItGivesUp) {
  receive(1, 0);
  beft::sender_state_t leaving = state(3, 1);
  leaving.leaving = true;
  leaving.process = "tasks";
  tracker.onState(leaving, 0, deliver);
  tracker.due(0, deliver);
  tracker.due(10'000'000, deliver);  // long silent: given up
  EXPECT_EQ(tracker.stats().lost, 2u);
  EXPECT_EQ(tracker.lostNamed(), (std::vector<std::string>{"VISION #2 of tasks (its sender left before it came)",
                                                           "VISION #3 of tasks (its sender left before it came)"}));
  receive(1, 0, 77);
  beft::sender_state_t moved_on = state(9, 5);
  moved_on.sender = 77;
  tracker.onState(moved_on, 10'000'000, deliver);
  ASSERT_EQ(tracker.lostNamed().size(), 5u);
  EXPECT_EQ(tracker.lostNamed()[2], "VISION #2 of 77 (no longer kept by its sender)");
}

TEST_F(Tracker, StreamsAreKeptApartBySenderAndAChannelNotTrackedIsLeftAlone) {
  receive(1, 0, 1);
  receive(1, 0, 2);
  EXPECT_EQ(handed.size(), 2u);
  EXPECT_FALSE(tracker.tracks("FIRE@1f"));
  beft::sender_state_t other = state(9, 1);
  other.channels = {"FIRE@1f"};
  tracker.onState(other, 0, deliver);
  EXPECT_TRUE(tracker.due(0, deliver).empty());
}

TEST_F(Tracker, ARecorderHandsOnWhatFollowsAGapAtOnceAndTheRepairOnce) {
  StreamTracker::Options options;
  options.hand_on_at_once = true;
  tracker = StreamTracker([](std::string_view) { return true; }, options);
  receive(1, 0);
  receive(3, 0);
  EXPECT_EQ(handed, (std::vector<std::string>{"m1", "m3"}));
  EXPECT_EQ(tracker.heldMessages(), 0u);
  ASSERT_EQ(tracker.due(0, deliver).at(0).sequences, (std::vector<int64_t>{2}));
  receive(3, 10);  // a copy
  receive(2, 20);
  receive(4, 30);
  EXPECT_EQ(handed, (std::vector<std::string>{"m1", "m3", "m2", "m4"}));
  EXPECT_EQ(tracker.stats().duplicates, 1u);
  EXPECT_EQ(tracker.missingMessages(), 0u);
}

TEST_F(Tracker, ADamagedEnvelopeCannotOpenAHugeGap) {
  receive(1, 0);
  receive(uint64_t{1} << 40, 0);
  EXPECT_EQ(tracker.stats().implausible, 1u);
  EXPECT_TRUE(tracker.due(0, deliver).empty());
  receive(2, 0);
  EXPECT_EQ(handed, (std::vector<std::string>{"m1", "m2"}));
}

TEST_F(Tracker, MeasuresTheRoundTripFromRepairs) {
  receive(1, 0);
  for (uint64_t sequence = 2; sequence < 60; sequence += 2) {
    const int64_t at = static_cast<int64_t>(sequence) * 100'000;
    receive(sequence + 1, at);
    tracker.due(at, deliver);
    receive(sequence, at + 300);  // answered 0.3 ms later
  }
  EXPECT_LT(tracker.roundTripUs(), 1500);
  EXPECT_GE(tracker.roundTripUs(), 300);
}

}  // namespace

// ChannelHistory: sequence numbers, bounded history, time lookups, "what is new".
#include <gtest/gtest.h>

#include <string>

#include "lib/wire/channel_history.hpp"

using beft::blackboard::ChannelHistory;

TEST(ChannelHistory, EmptyHasNoLatestAndSequenceZero) {
  ChannelHistory<int> history(4);
  EXPECT_TRUE(history.empty());
  EXPECT_EQ(history.lastSequence(), 0u);
  EXPECT_EQ(history.latest(), nullptr);
  EXPECT_EQ(history.oldest(), nullptr);
  EXPECT_EQ(history.atOrBefore(1000), nullptr);
  EXPECT_TRUE(history.since(0).empty());
  EXPECT_FALSE(history.dropOldest());
}

TEST(ChannelHistory, SequenceNumbersStartAtOneAndGrowByOne) {
  ChannelHistory<std::string> history(8);
  EXPECT_EQ(history.store("a", 100), 1u);
  EXPECT_EQ(history.store("b", 200), 2u);
  EXPECT_EQ(history.store("c", 300), 3u);
  EXPECT_EQ(history.lastSequence(), 3u);
  ASSERT_NE(history.latest(), nullptr);
  EXPECT_EQ(history.latest()->message, "c");
  EXPECT_EQ(history.latest()->sequence, 3u);
  EXPECT_EQ(history.latest()->utime, 300);
}

TEST(ChannelHistory, KeepsOnlyTheNewestCapacityEntries) {
  ChannelHistory<int> history(3);
  for (int i = 1; i <= 10; ++i) history.store(i * 10, i * 1000);
  EXPECT_EQ(history.size(), 3u);
  EXPECT_EQ(history.capacity(), 3u);
  EXPECT_EQ(history.oldest()->message, 80);
  EXPECT_EQ(history.oldest()->sequence, 8u);
  EXPECT_EQ(history.latest()->message, 100);
  // Sequence numbers keep counting although old entries are gone.
  EXPECT_EQ(history.lastSequence(), 10u);
}

TEST(ChannelHistory, ZeroCapacityStillKeepsTheLatest) {
  ChannelHistory<int> history(0);
  history.store(1, 1);
  history.store(2, 2);
  EXPECT_EQ(history.size(), 1u);
  EXPECT_EQ(history.latest()->message, 2);
}

TEST(ChannelHistory, AtOrBeforeGivesTheStateAsOfATime) {
  ChannelHistory<int> history(10);
  history.store(1, 100);
  history.store(2, 200);
  history.store(3, 300);
  EXPECT_EQ(history.atOrBefore(99), nullptr);
  EXPECT_EQ(history.atOrBefore(100)->message, 1);
  EXPECT_EQ(history.atOrBefore(250)->message, 2);
  EXPECT_EQ(history.atOrBefore(300)->message, 3);
  EXPECT_EQ(history.atOrBefore(1'000'000)->message, 3);
  EXPECT_EQ(history.at(200)->message, 2);
  EXPECT_EQ(history.at(250), nullptr);
}

TEST(ChannelHistory, AtOrBeforeIgnoresEntriesDroppedFromTheHistory) {
  ChannelHistory<int> history(2);
  history.store(1, 100);
  history.store(2, 200);
  history.store(3, 300);
  EXPECT_EQ(history.atOrBefore(150), nullptr);  // utime 100 was dropped
  EXPECT_EQ(history.atOrBefore(250)->message, 2);
}

TEST(ChannelHistory, SinceReturnsOnlyNewerEntriesOldestFirst) {
  ChannelHistory<int> history(10);
  for (int i = 1; i <= 5; ++i) history.store(i, i * 100);
  const auto newer = history.since(3);
  ASSERT_EQ(newer.size(), 2u);
  EXPECT_EQ(newer[0].sequence, 4u);
  EXPECT_EQ(newer[0].message, 4);
  EXPECT_EQ(newer[1].sequence, 5u);
  EXPECT_TRUE(history.since(5).empty());
  EXPECT_EQ(history.since(0).size(), 5u);
}

TEST(ChannelHistory, SinceAReaderThatFellBehindGetsWhatIsLeft) {
  ChannelHistory<int> history(3);
  for (int i = 1; i <= 10; ++i) history.store(i, i);
  const auto newer = history.since(2);  // 3..7 were dropped
  ASSERT_EQ(newer.size(), 3u);
  EXPECT_EQ(newer.front().sequence, 8u);
  EXPECT_EQ(newer.back().sequence, 10u);
}

TEST(ChannelHistory, DropOldestRemovesOneEntryAndKeepsSequences) {
  ChannelHistory<int> history(5);
  history.store(1, 1);
  history.store(2, 2);
  EXPECT_TRUE(history.dropOldest());
  EXPECT_EQ(history.size(), 1u);
  EXPECT_EQ(history.oldest()->message, 2);
  EXPECT_EQ(history.store(3, 3), 3u);
}

// The message dropped to make room is handed back (a reader decodes the
// next one over it), the one before it stays dropped; none before full.
TEST(ChannelHistory, HandsBackTheMessageDroppedToMakeRoom) {
  ChannelHistory<std::string> history(2);
  std::string dropped = "untouched";
  history.store(std::string("first"), 100, &dropped);
  history.store(std::string("second"), 200, &dropped);
  EXPECT_EQ(dropped, "untouched");
  history.store(std::string("third"), 300, &dropped);
  EXPECT_EQ(dropped, "first");
  history.store(std::string("fourth"), 400, &dropped);
  EXPECT_EQ(dropped, "second");
  EXPECT_EQ(history.oldest()->message, "third");
  EXPECT_EQ(history.latest()->message, "fourth");
}

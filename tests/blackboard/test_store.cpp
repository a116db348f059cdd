// Store (utime extraction, bounds, byte budget), snapshots and the channel filter.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include <beft/bb_query_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/run_status_t.hpp>

#include "blackboard/channel_filter.hpp"
#include "blackboard/snapshot.hpp"
#include "blackboard/store.hpp"

using namespace beft::blackboard;

namespace {

template <typename Message>
std::vector<uint8_t> encode(const Message& message) {
  std::vector<uint8_t> bytes(message.getEncodedSize());
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

std::vector<uint8_t> robotState(int64_t utime, double x) {
  beft::robot_state_t state{};
  state.utime = utime;
  state.tick = utime / 100000;
  state.x = x;
  state.last_command = "stop";
  return encode(state);
}

template <typename Message>
Message decode(const std::vector<uint8_t>& bytes) {
  Message message;
  EXPECT_EQ(message.decode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  return message;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

TEST(EncodedUtime, ReadsTheBigEndianUtimeAfterTheFingerprint) {
  const auto bytes = robotState(123456789012345, 1.0);
  ASSERT_TRUE(encodedUtime(bytes.data(), static_cast<int>(bytes.size())).has_value());
  EXPECT_EQ(*encodedUtime(bytes.data(), static_cast<int>(bytes.size())), 123456789012345);

  beft::run_status_t status{};
  status.utime = -5;  // negative values survive the sign
  status.message = "x";
  const auto status_bytes = encode(status);
  EXPECT_EQ(*encodedUtime(status_bytes.data(), static_cast<int>(status_bytes.size())), -5);
}

TEST(EncodedUtime, NothingForMessagesShorterThanFingerprintAndUtime) {
  const std::vector<uint8_t> short_message(15, 0xff);
  EXPECT_FALSE(encodedUtime(short_message.data(), 15).has_value());
  EXPECT_FALSE(encodedUtime(nullptr, 0).has_value());
}

TEST(Store, StoresPerChannelWithSequenceAndUtime) {
  Store store(Store::Limits{10, 1u << 20});
  const auto a = robotState(1'000'000, 1.5);
  const auto b = robotState(2'000'000, 2.5);
  EXPECT_EQ(store.store("ROBOT_STATE", a.data(), static_cast<int>(a.size())), 1u);
  EXPECT_EQ(store.store("ROBOT_STATE", b.data(), static_cast<int>(b.size())), 2u);
  EXPECT_EQ(store.store("OTHER", a.data(), static_cast<int>(a.size())), 1u);

  EXPECT_EQ(store.channelCount(), 2u);
  EXPECT_EQ(store.messagesStored(), 3u);
  EXPECT_EQ(store.bytesHeld(), 2 * a.size() + b.size());
  const auto* latest = store.latest("ROBOT_STATE");
  ASSERT_NE(latest, nullptr);
  EXPECT_EQ(latest->sequence, 2u);
  EXPECT_EQ(latest->utime, 2'000'000);
  EXPECT_EQ(latest->message, b);
  EXPECT_DOUBLE_EQ(decode<beft::robot_state_t>(latest->message).x, 2.5);
  EXPECT_EQ(store.history("ROBOT_STATE")->atOrBefore(1'500'000)->message, a);
  EXPECT_EQ(store.latest("MISSING"), nullptr);
  EXPECT_EQ(store.channels(), (std::vector<std::string>{"OTHER", "ROBOT_STATE"}));
}

TEST(Store, RejectsMessagesTooShortForAUtime) {
  Store store(Store::Limits{});
  const std::vector<uint8_t> garbage(10, 1);
  EXPECT_FALSE(store.store("X", garbage.data(), 10).has_value());
  EXPECT_EQ(store.channelCount(), 0u);
  EXPECT_EQ(store.messagesRejected(), 1u);
}

TEST(Store, HistoryIsBoundedAndBytesAreAccounted) {
  Store store(Store::Limits{3, 1u << 20});
  std::size_t size = 0;
  for (int i = 1; i <= 7; ++i) {
    const auto bytes = robotState(i * 100000, i);
    size = bytes.size();
    store.store("ROBOT_STATE", bytes.data(), static_cast<int>(bytes.size()));
  }
  const auto* history = store.history("ROBOT_STATE");
  ASSERT_NE(history, nullptr);
  EXPECT_EQ(history->size(), 3u);
  EXPECT_EQ(history->oldest()->sequence, 5u);
  EXPECT_EQ(history->latest()->sequence, 7u);
  EXPECT_EQ(store.bytesHeld(), 3 * size);
  EXPECT_EQ(store.messagesStored(), 7u);
}

TEST(Store, ByteBudgetDropsOldestButAlwaysKeepsTheLatest) {
  const auto sample = robotState(0, 0);
  // Room for two messages.
  Store store(Store::Limits{100, 2 * sample.size() + 1});
  for (int i = 1; i <= 5; ++i) {
    const auto bytes = robotState(i, i);
    store.store("ROBOT_STATE", bytes.data(), static_cast<int>(bytes.size()));
  }
  EXPECT_EQ(store.history("ROBOT_STATE")->size(), 2u);
  EXPECT_EQ(store.history("ROBOT_STATE")->oldest()->sequence, 4u);
  EXPECT_EQ(store.bytesHeld(), 2 * sample.size());

  Store tiny(Store::Limits{100, 1});  // smaller than any message
  tiny.store("ROBOT_STATE", sample.data(), static_cast<int>(sample.size()));
  tiny.store("ROBOT_STATE", sample.data(), static_cast<int>(sample.size()));
  ASSERT_NE(tiny.latest("ROBOT_STATE"), nullptr);
  EXPECT_EQ(tiny.latest("ROBOT_STATE")->sequence, 2u);
  EXPECT_EQ(tiny.history("ROBOT_STATE")->size(), 1u);
}

TEST(Snapshot, LatestOfEachAskedChannelWithSequenceUtimeAndBytes) {
  Store store(Store::Limits{});
  for (int i = 1; i <= 4; ++i) {
    const auto bytes = robotState(i * 1000, 10.0 + i);
    store.store("ROBOT_STATE", bytes.data(), static_cast<int>(bytes.size()));
  }
  const auto other = robotState(77, 7);
  store.store("B", other.data(), static_cast<int>(other.size()));
  store.store("C", other.data(), static_cast<int>(other.size()));

  beft::bb_query_t query{};
  query.query_id = 42;
  query.channels = {"ROBOT_STATE", "B", "NOT_THERE"};
  query.num_channels = 3;
  const auto snapshot = buildSnapshot(store, query, 999);
  EXPECT_EQ(snapshot.query_id, 42);
  EXPECT_EQ(snapshot.utime, 999);
  ASSERT_EQ(snapshot.num_entries, 2);
  ASSERT_EQ(snapshot.entries.size(), 2u);
  EXPECT_EQ(snapshot.entries[0].channel, "B");
  EXPECT_EQ(snapshot.entries[1].channel, "ROBOT_STATE");
  EXPECT_EQ(snapshot.entries[1].sequence, 4);
  EXPECT_EQ(snapshot.entries[1].utime, 4000);
  EXPECT_EQ(snapshot.entries[1].data_size, static_cast<int32_t>(snapshot.entries[1].data.size()));
  EXPECT_DOUBLE_EQ(decode<beft::robot_state_t>(snapshot.entries[1].data).x, 14.0);
  EXPECT_EQ(missingChannels(store, query), std::vector<std::string>{"NOT_THERE"});

  // The snapshot survives its own encoding.
  const auto round_trip = decode<beft::bb_snapshot_t>(encode(snapshot));
  EXPECT_EQ(round_trip.entries[1].data, snapshot.entries[1].data);
}

TEST(Snapshot, NoChannelsNamedMeansEveryChannel) {
  Store store(Store::Limits{});
  const auto bytes = robotState(5, 5);
  for (const char* channel : {"X", "A", "M"}) store.store(channel, bytes.data(), static_cast<int>(bytes.size()));
  beft::bb_query_t query{};
  const auto snapshot = buildSnapshot(store, query, 0);
  ASSERT_EQ(snapshot.entries.size(), 3u);
  EXPECT_EQ(snapshot.entries[0].channel, "A");
  EXPECT_EQ(snapshot.entries[2].channel, "X");
  EXPECT_EQ(snapshotChannel("vision"), "BB_SNAPSHOT_vision");
}

TEST(ChannelFilter, DefaultExcludesTheControlPlaneAndTheService) {
  ChannelFilter filter(ChannelFilter::defaultExclusions());
  for (const char* excluded : {"FIRE", "DONE", "HEARTBEAT", "MARKING", "BB_QUERY", "BB_SNAPSHOT_vision"})
    EXPECT_FALSE(filter.accepts(excluded)) << excluded;
  for (const char* kept : {"ROBOT_STATE", "HYPOTHESES", "FIRED", "XFIRE", "CAMERA_COLOR"})
    EXPECT_TRUE(filter.accepts(kept)) << kept;
  EXPECT_TRUE(contains(filter.patterns(), "BB_.*"));
}

TEST(ChannelFilter, CustomPatternsMatchWholeNames) {
  ChannelFilter filter({"CAMERA_.*", "LABELS_VISUAL|AUDIO"});
  EXPECT_FALSE(filter.accepts("CAMERA_DEPTH"));
  EXPECT_FALSE(filter.accepts("AUDIO"));
  EXPECT_FALSE(filter.accepts("LABELS_VISUAL"));
  EXPECT_TRUE(filter.accepts("LABELS_VISUAL_2"));  // the alternation is anchored as a whole
  EXPECT_TRUE(filter.accepts("MY_AUDIO"));
  EXPECT_TRUE(filter.accepts("MY_CAMERA_DEPTH"));
  EXPECT_TRUE(filter.accepts("FIRE"));  // not in this list
}

TEST(ChannelFilter, BadPatternIsReportedByName) {
  try {
    ChannelFilter filter({"OK", "BROKEN[("});  // unterminated bracket
    FAIL() << "a broken pattern was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("BROKEN[("), std::string::npos);
  }
}

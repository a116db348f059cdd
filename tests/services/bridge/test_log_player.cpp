// A run's log indexed once and played: at a speed, a tick at a time, from any time.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "lib/common/channels.hpp"
#include "services/bridge/log_index.hpp"
#include "services/bridge/log_player.hpp"

using namespace beft::bridge;
using Clock = LogPlayer::Clock;

namespace {

const std::string kLog = std::string(BEFT_SOURCE_DIR) + "/tests/system/data/peek_6_ticks.lcmlog";

struct Heard {
  std::vector<std::string> channels;
  std::vector<int64_t> times;
  void operator()(const beft::wire::LogEvent& e) {
    channels.push_back(e.channel);
    times.push_back(e.timestamp);
  }
  int count(const std::string& channel) const {
    return static_cast<int>(std::count(channels.begin(), channels.end(), channel));
  }
};

}  // namespace

TEST(LogIndex, IndexesTimeAndKeyframes) {
  const LogIndex index = buildLogIndex(kLog, 100000);
  EXPECT_GT(index.events, 100u);
  EXPECT_LT(index.start_utime, index.end_utime);
  ASSERT_GE(index.checkpoints.size(), 2u);
  for (std::size_t i = 1; i < index.checkpoints.size(); ++i) {
    EXPECT_LT(index.checkpoints[i - 1].utime, index.checkpoints[i].utime);
    EXPECT_LT(index.checkpoints[i - 1].offset, index.checkpoints[i].offset);
  }
  ASSERT_TRUE(index.keyframes.count(beft::channels::kGroundTruth.name));
  EXPECT_TRUE(index.damage.empty());
  // Rebuilding the state at the end starts no later than the scene's last keyframe.
  EXPECT_LE(index.offsetToRebuild(index.end_utime), index.keyframes.at(beft::channels::kGroundTruth.name).back().offset);
  EXPECT_EQ(index.offsetToRebuild(index.start_utime - 1), 0u);
}

TEST(LogPlayer, PlaysAtItsSpeedToTheEnd) {
  const LogIndex index = buildLogIndex(kLog);
  Heard heard;
  LogPlayer player(index, std::ref(heard));
  EXPECT_FALSE(player.playing());
  const auto t0 = Clock::now();
  player.play(2.0, t0);
  const int64_t span = index.end_utime - index.start_utime;
  player.advance(t0 + std::chrono::microseconds(span / 4));  // half the log at speed 2
  EXPECT_NEAR(player.time() - index.start_utime, span / 2, span / 50);
  EXPECT_LT(heard.channels.size(), index.events);
  player.advance(t0 + std::chrono::microseconds(span));
  EXPECT_EQ(heard.channels.size(), index.events);
  EXPECT_TRUE(player.atEnd());
  EXPECT_FALSE(player.playing());
}

TEST(LogPlayer, StepsOneTickAndSeeks) {
  const LogIndex index = buildLogIndex(kLog);
  Heard heard;
  LogPlayer player(index, std::ref(heard));
  const std::string tick = player.tickChannel();
  player.step();
  const int first = heard.count(tick);
  EXPECT_GE(first, 1);
  player.step();
  EXPECT_EQ(heard.count(tick), first + 1);
  EXPECT_FALSE(player.playing());

  Heard rebuilt;
  LogPlayer seeker(index, std::ref(rebuilt));
  rebuilt.channels.clear();
  seeker.seek(index.end_utime);
  // One message of each channel (its latest), every keyframed one among them.
  const std::set<std::string> distinct(rebuilt.channels.begin(), rebuilt.channels.end());
  EXPECT_EQ(distinct.size(), rebuilt.channels.size());
  for (const auto& channel : keyframedChannels())
    if (index.channels.count(channel)) {
      EXPECT_TRUE(distinct.count(channel)) << channel;
    }
  EXPECT_TRUE(distinct.count(beft::channels::kGroundTruth.name));
  EXPECT_TRUE(distinct.count(seeker.tickChannel()));
  EXPECT_EQ(seeker.time(), index.end_utime);
}

TEST(LogIndex, ReadsADamagedLogUpToWhereItBreaks) {
  const std::string cut =
      (std::filesystem::temp_directory_path() / ("beft_cut_" + std::to_string(getpid()) + ".lcmlog")).string();
  const auto size = std::filesystem::file_size(kLog);
  {
    std::ifstream in(kLog, std::ios::binary);
    std::string bytes(size / 2, '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    std::ofstream(cut, std::ios::binary) << bytes;
  }
  const LogIndex whole = buildLogIndex(kLog);
  const LogIndex half = buildLogIndex(cut);
  EXPECT_GT(half.events, 0u);
  EXPECT_LT(half.events, whole.events);
  EXPECT_FALSE(half.damage.empty());
  Heard heard;
  LogPlayer player(half, std::ref(heard));
  player.play(1000.0, Clock::now());
  player.advance(Clock::now() + std::chrono::hours(1));
  EXPECT_EQ(heard.channels.size(), half.events);
  std::filesystem::remove(cut);
}

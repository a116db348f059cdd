// The log reader: whole logs as lcm-logger writes them, and logs with
// garbage, damaged headers, foreign bytes and a cut last event.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lib/wire/log_reader.hpp"
#include "lib/wire/run_identity.hpp"

using beft::wire::LogEvent;
using beft::wire::LogReader;

namespace {

class TempLog {
 public:
  TempLog() : path_(::testing::TempDir() + "log_reader_" + std::to_string(getpid()) + "_" + std::to_string(next_++) + ".lcm") {}
  ~TempLog() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

  // n events written by LCM's own writer: channel "CH<i>", i+1 bytes of value i.
  void writeWithLcm(int n) {
    lcm::LogFile log(path_, "w");
    for (int i = 0; i < n; ++i) {
      std::vector<uint8_t> data(static_cast<std::size_t>(i + 1), static_cast<uint8_t>(i));
      lcm::LogEvent event{};
      event.eventnum = i;
      event.timestamp = 1000 + i;
      event.channel = "CH" + std::to_string(i);
      event.datalen = static_cast<int32_t>(data.size());
      event.data = data.data();
      log.writeEvent(&event);
    }
  }
  // One small event per channel, in order.
  void writeChannels(const std::vector<std::string>& channels) {
    lcm::LogFile log(path_, "w");
    const uint8_t payload[4] = {1, 2, 3, 4};
    for (std::size_t i = 0; i < channels.size(); ++i) {
      lcm::LogEvent event{};
      event.eventnum = static_cast<int64_t>(i);
      event.timestamp = 1000 + static_cast<int64_t>(i);
      event.channel = channels[i];
      event.datalen = sizeof payload;
      event.data = const_cast<uint8_t*>(payload);
      log.writeEvent(&event);
    }
  }
  std::vector<uint8_t> bytes() const {
    std::ifstream in(path_, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
  }
  void setBytes(const std::vector<uint8_t>& bytes) const {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }

 private:
  static inline int next_ = 0;
  std::string path_;
};

std::vector<std::string> channelsOf(LogReader& reader) {
  std::vector<std::string> channels;
  LogEvent event;
  while (reader.next(event)) channels.push_back(event.channel);
  return channels;
}

// Offset of event i in a log written by writeWithLcm: header 28 bytes + channel + data.
std::size_t offsetOf(int index) {
  std::size_t offset = 0;
  for (int i = 0; i < index; ++i) offset += 28 + ("CH" + std::to_string(i)).size() + static_cast<std::size_t>(i + 1);
  return offset;
}

}  // namespace

TEST(LogReader, ReadsWhatLcmWritesEventByEvent) {
  TempLog log;
  log.writeWithLcm(5);
  LogReader reader(log.path());
  LogEvent event;
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(reader.next(event));
    EXPECT_EQ(event.channel, "CH" + std::to_string(i));
    EXPECT_EQ(event.timestamp, 1000 + i);
    EXPECT_EQ(event.data, std::vector<uint8_t>(static_cast<std::size_t>(i + 1), static_cast<uint8_t>(i)));
  }
  EXPECT_FALSE(reader.next(event));
  EXPECT_FALSE(reader.damage().any());
  EXPECT_EQ(reader.position(), log.bytes().size());
}

TEST(LogReader, ACutLastEventIsReportedAndTheRestRead) {
  TempLog log;
  log.writeWithLcm(6);
  auto bytes = log.bytes();
  for (std::size_t cut = offsetOf(5) + 1; cut < bytes.size(); cut += 3) {
    log.setBytes(std::vector<uint8_t>(bytes.begin(), bytes.begin() + static_cast<long>(cut)));
    LogReader reader(log.path());
    EXPECT_EQ(channelsOf(reader).size(), 5u) << "cut at " << cut;
    EXPECT_TRUE(reader.damage().cut_at_end) << "cut at " << cut;
    EXPECT_EQ(reader.position(), offsetOf(5));
  }
}

TEST(LogReader, GarbageBetweenEventsIsSkippedAndCounted) {
  TempLog log;
  log.writeWithLcm(6);
  auto bytes = log.bytes();
  std::vector<uint8_t> garbage(333, 0xAB);
  bytes.insert(bytes.begin() + static_cast<long>(offsetOf(3)), garbage.begin(), garbage.end());
  log.setBytes(bytes);
  LogReader reader(log.path());
  EXPECT_EQ(channelsOf(reader), (std::vector<std::string>{"CH0", "CH1", "CH2", "CH3", "CH4", "CH5"}));
  EXPECT_EQ(reader.damage().damaged_stretches, 1u);
  EXPECT_EQ(reader.damage().bytes_skipped, 333u);
  EXPECT_NE(reader.damage().summary().find("1 damaged stretch"), std::string::npos);
}

TEST(LogReader, ADamagedLengthCostsOnlyItsOwnEvent) {
  TempLog log;
  log.writeWithLcm(6);
  for (uint32_t length : {0x7fffffffu, 0xffffffffu, 5000u}) {
    auto bytes = log.bytes();
    const std::size_t data_length_at = offsetOf(2) + 24;
    for (int i = 0; i < 4; ++i) bytes[data_length_at + i] = static_cast<uint8_t>(length >> (24 - 8 * i));
    TempLog damaged;
    damaged.setBytes(bytes);
    LogReader reader(damaged.path());
    EXPECT_EQ(channelsOf(reader), (std::vector<std::string>{"CH0", "CH1", "CH3", "CH4", "CH5"})) << length;
    EXPECT_EQ(reader.damage().damaged_stretches, 1u) << length;
    EXPECT_FALSE(reader.damage().cut_at_end) << length;
  }
}

TEST(LogReader, RandomBytesEndWithoutThrowingOrLooping) {
  TempLog log;
  std::vector<uint8_t> bytes(100000);
  uint32_t state = 12345;
  for (auto& b : bytes) b = static_cast<uint8_t>((state = state * 1664525u + 1013904223u) >> 24);
  // A few sync words with absurd headers inside.
  for (std::size_t at = 100; at + 4 < bytes.size(); at += 9973) {
    bytes[at] = 0xED; bytes[at + 1] = 0xA1; bytes[at + 2] = 0xDA; bytes[at + 3] = 0x01;
  }
  log.setBytes(bytes);
  LogReader reader(log.path());
  LogEvent event;
  int events = 0;
  while (reader.next(event)) ++events;
  EXPECT_LE(events, 11);
  EXPECT_TRUE(reader.damage().any());
}

TEST(LogReader, FollowsALogFromAnEarlierPosition) {
  TempLog log;
  log.writeWithLcm(4);
  LogReader first(log.path());
  LogEvent event;
  ASSERT_TRUE(first.next(event));
  ASSERT_TRUE(first.next(event));
  LogReader rest(log.path(), first.position());
  EXPECT_EQ(channelsOf(rest), (std::vector<std::string>{"CH2", "CH3"}));
}

TEST(LogReader, AMissingFileIsAClearError) {
  try {
    LogReader reader("/nonexistent/run.lcm");
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/run.lcm"), std::string::npos);
  }
}

TEST(RunOfLog, IsTheArbitersRunAndAPlainForgedFireBeforeItIsForeign) {
  using beft::wire::runChannel;
  using beft::wire::runOfLog;
  const int64_t run = 0x1f3a5c7e9b2d4f60, other = 0x0123456789abcdef;
  TempLog forged;
  forged.writeChannels({"FIRE", "RUN_STATUS", runChannel("VISION", run), runChannel("MARKING", run)});
  EXPECT_EQ(runOfLog(forged.path()), run);
  TempLog without_arbiter;  // only data channels with an id: their run
  without_arbiter.writeChannels({"GEOMETRY", runChannel("VISION", run), runChannel("FIRE", other)});
  EXPECT_EQ(runOfLog(without_arbiter.path()), other);
  TempLog data_only;
  data_only.writeChannels({"GEOMETRY", runChannel("VISION", run)});
  EXPECT_EQ(runOfLog(data_only.path()), run);
  TempLog old;  // recorded before runs had ids
  old.writeChannels({"MARKING", "FIRE", "VISION"});
  EXPECT_EQ(runOfLog(old.path()), 0);
  // Read as its run, the forged log's plain channels are another run's.
  LogReader reader(forged.path());
  LogEvent event;
  std::vector<std::string> read;
  while (reader.nextOfRun(event, run)) read.push_back(event.channel);
  EXPECT_EQ(read, (std::vector<std::string>{"VISION", "MARKING"}));
  EXPECT_EQ(reader.otherRunEvents(), 2u);
}

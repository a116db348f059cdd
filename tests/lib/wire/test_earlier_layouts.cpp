// Logs recorded before a type changed read as today's layout: the short peek
// run committed as test data holds camera frames from before `compression`.
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <string>
#include <vector>

#include <beft/camera_frame_t.hpp>
#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/run_beacon_t.hpp>

#include "lib/wire/earlier_layouts.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/lcm_schema.hpp"
#include "lib/wire/log_reader.hpp"

using namespace beft::wire;

namespace {

const std::string kOldLog = std::string(BEFT_SOURCE_DIR) + "/tests/system/data/peek_6_ticks.lcmlog";

uint64_t fingerprintOf(const std::vector<uint8_t>& data) {
  uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value = (value << 8) | data[i];
  return value;
}

}  // namespace

TEST(EarlierLayouts, AnOldCameraFrameGainsItsCompressionByteAndNothingElseChanges) {
  // The file's bytes as written, through LCM's own reader (no upgrade).
  lcm::LogFile file(kOldLog, "r");
  ASSERT_TRUE(file.good());
  int frames = 0, others = 0;
  while (const lcm::LogEvent* event = file.readNextEvent()) {
    const auto* bytes = static_cast<const uint8_t*>(event->data);
    const std::vector<uint8_t> original(bytes, bytes + event->datalen);
    std::vector<uint8_t> data = original;
    const std::string channel = event->channel;
    const bool camera = channel.rfind("CAMERA_", 0) == 0;
    // FIRE and DONE gained members at their end too (checked in their own test).
    const bool control = channel == "FIRE" || channel == "DONE";
    EXPECT_EQ(upgradeEarlierLayout(data), camera || control) << event->channel;
    if (!camera) {
      if (!control) EXPECT_EQ(data, original);
      ++others;
      continue;
    }
    ASSERT_EQ(data.size(), original.size() + 1);
    EXPECT_EQ(fingerprintOf(data), static_cast<uint64_t>(beft::camera_frame_t::getHash()));
    EXPECT_NE(fingerprintOf(original), fingerprintOf(data));
    EXPECT_TRUE(std::equal(original.begin() + 8, original.begin() + 25, data.begin() + 8));
    EXPECT_EQ(data[25], beft::camera_frame_t::COMPRESSION_NONE);
    EXPECT_TRUE(std::equal(original.begin() + 25, original.end(), data.begin() + 26));
    // Today's layout is left as it is.
    std::vector<uint8_t> again = data;
    EXPECT_FALSE(upgradeEarlierLayout(again));
    EXPECT_EQ(again, data);
    ++frames;
  }
  EXPECT_EQ(frames, 18);
  EXPECT_GT(others, 100);
}

TEST(EarlierLayouts, TheLogReaderHandsOutOldFramesInTodaysLayout) {
  LogReader log(kOldLog);
  LogEvent event;
  int frames = 0;
  while (log.next(event)) {
    if (event.channel.rfind("CAMERA_", 0) != 0) continue;
    beft::camera_frame_t frame{};
    const Verdict verdict = guardedDecode(event.data.data(), event.data.size(), frame);
    ASSERT_TRUE(verdict.ok()) << event.channel << ": " << verdict.text();
    EXPECT_EQ(frame.compression, beft::camera_frame_t::COMPRESSION_NONE);
    EXPECT_EQ(frame.data_size, frame.width * frame.height * (frame.encoding == frame.ENCODING_RGB8 ? 3 : 2));
    ++frames;
  }
  EXPECT_EQ(frames, 18);
  EXPECT_FALSE(log.damage().any());
}

TEST(EarlierLayouts, ShortOrForeignBytesAreLeftAlone) {
  std::vector<uint8_t> short_bytes(20, 0xff);
  EXPECT_FALSE(upgradeEarlierLayout(short_bytes));
  EXPECT_EQ(short_bytes.size(), 20u);
  beft::fire_t fire{};
  fire.expert = "vision";
  fire.transition = "t";
  std::vector<uint8_t> bytes(fire.getEncodedSize());
  fire.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  const std::vector<uint8_t> original = bytes;
  EXPECT_FALSE(upgradeEarlierLayout(bytes));
  EXPECT_EQ(bytes, original);
}

// A beacon from before `description` and `started_utime` (an arbiter of an
// older build, in its log): the same bytes without them, read as today's with
// both 0, "not known", so a launcher never takes it for a run of its launch.
TEST(EarlierLayouts, AnOldRunBeaconGainsAnUnknownDescriptionAndStart) {
  LcmTypeSet earlier;
  earlier.addSchema("run_beacon_t.lcm (earlier)", R"(package beft;
struct run_beacon_t
{
    int64_t utime;
    int64_t run_id;
    string  host;
    int32_t pid;
    int64_t tick;
}
)");
  earlier.finalize();
  beft::run_beacon_t today{};
  today.utime = 1'700'000'000'000'000;
  today.run_id = 0x1f3a;
  today.host = "sim";
  today.pid = 42;
  today.tick = 17;
  std::vector<uint8_t> expected(today.getEncodedSize());
  today.encode(expected.data(), 0, static_cast<int>(expected.size()));
  std::vector<uint8_t> old(expected.begin(), expected.end() - 16);  // without the two new members
  const uint64_t old_fingerprint = earlier.fingerprint("beft.run_beacon_t");
  ASSERT_NE(old_fingerprint, fingerprintOf(expected));
  for (int i = 0; i < 8; ++i) old[i] = static_cast<uint8_t>(old_fingerprint >> (56 - 8 * i));

  ASSERT_TRUE(upgradeEarlierLayout(old));
  EXPECT_EQ(old, expected);
  beft::run_beacon_t read{};
  ASSERT_TRUE(guardedDecode(old.data(), old.size(), read).ok());
  EXPECT_EQ(read.run_id, 0x1f3a);
  EXPECT_EQ(read.tick, 17);
  EXPECT_EQ(read.description, 0);
  EXPECT_EQ(read.started_utime, 0);
  EXPECT_FALSE(upgradeEarlierLayout(old));  // today's layout is left as it is
}

// FIREs and DONEs of a log recorded before loss repair: today's layout, coming
// after nothing and listing nothing published.
TEST(EarlierLayouts, OldFiresAndDonesComeAfterNothingAndListNothing) {
  beft::wire::LogReader reader(kOldLog);
  beft::wire::LogEvent event;
  int fires = 0, dones = 0;
  while (reader.next(event)) {
    if (event.channel == "FIRE") {
      beft::fire_t fire;
      ASSERT_TRUE(beft::wire::guardedDecode(event.data.data(), event.data.size(), fire).ok());
      EXPECT_EQ(fire.after_sender, 0);
      EXPECT_EQ(fire.after_frontier, 0);
      EXPECT_FALSE(fire.expert.empty());
      ++fires;
    } else if (event.channel == "DONE") {
      beft::done_t done;
      ASSERT_TRUE(beft::wire::guardedDecode(event.data.data(), event.data.size(), done).ok());
      EXPECT_EQ(done.sender, 0);
      EXPECT_EQ(done.num_published, 0);
      EXPECT_TRUE(done.published_channels.empty());
      ++dones;
    }
  }
  EXPECT_GT(fires, 0);
  EXPECT_GT(dones, 0);
}

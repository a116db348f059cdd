// Logs recorded before a type changed read as today's layout: the short peek
// run committed as test data holds camera frames from before `compression`.
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <string>
#include <vector>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/camera_frame_t.hpp>
#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/hypothesis_changes_t.hpp>
#include <beft/run_beacon_t.hpp>

#include "lib/wire/earlier_layouts.hpp"
#include "lib/wire/embedded_schemas.hpp"
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
    // FIRE and DONE gained members at their end too, hypotheses and acoustic
    // percepts at the end of each element (checked in their own tests).
    const bool control =
        channel == "FIRE" || channel == "DONE" || channel == "AUDIO" || channel == "HYPOTHESES";
    EXPECT_EQ(upgradeEarlierLayout(data), camera || control) << event->channel;
    if (!camera) {
      if (!control) {
        EXPECT_EQ(data, original);
      }
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

namespace {

template <typename Message>
std::vector<uint8_t> encodedMessage(const Message& m) {
  std::vector<uint8_t> bytes(m.getEncodedSize());
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

// The bytes of `today` as the earlier layout had them: each element's last
// byte (its `located`) left out, the earlier fingerprint first.
template <typename Element>
std::vector<uint8_t> withoutLastByteOfEach(const std::vector<uint8_t>& today, std::size_t elements_start,
                                           const std::vector<Element>& elements, uint64_t earlier_fingerprint) {
  std::vector<uint8_t> old(today.begin(), today.begin() + static_cast<std::ptrdiff_t>(elements_start));
  std::size_t at = elements_start;
  for (const Element& element : elements) {
    const auto size = static_cast<std::size_t>(element._getEncodedSizeNoHash());
    old.insert(old.end(), today.begin() + static_cast<std::ptrdiff_t>(at),
               today.begin() + static_cast<std::ptrdiff_t>(at + size - 1));
    at += size;
  }
  old.insert(old.end(), today.begin() + static_cast<std::ptrdiff_t>(at), today.end());
  for (int i = 0; i < 8; ++i) old[i] = static_cast<uint8_t>(earlier_fingerprint >> (56 - 8 * i));
  return old;
}

beft::hypothesis_t hypothesisNamed(const std::string& id, int categories) {
  beft::hypothesis_t h{};
  h.object_id = id;
  h.x = 1.5;
  h.best_category = "person";
  h.num_categories = categories;
  for (int i = 0; i < categories; ++i) {
    h.categories.push_back("c" + std::to_string(i));
    h.fused.push_back(0.1 * i);
  }
  h.heard = true;
  h.heard_as = "person";
  h.settled_utime = 9;
  return h;
}

}  // namespace

// Hypotheses from before `located`: each element gains it as false (not
// known to be located), whatever the lengths of the strings and arrays
// before it, and nothing else changes.
TEST(EarlierLayouts, OldHypothesesGainLocatedFalseInEachElement) {
  LcmTypeSet earlier;
  for (const EmbeddedSchema& schema : embeddedLcmSchemas())
    if (schema.file != "hypothesis_t.lcm") earlier.addSchema(schema.file, schema.text);
  earlier.addSchema("hypothesis_t.lcm (earlier)", R"(package beft;
struct hypothesis_t
{
    string  object_id;
    double  x;
    double  y;
    double  z;
    string  best_category;
    double  confidence;
    int32_t num_categories;
    string  categories[num_categories];
    double  fused[num_categories];
    boolean seen;
    boolean heard;
    string  seen_as;
    string  heard_as;
    boolean verified;
    boolean falsified;
    int64_t first_heard_utime;
    int64_t first_seen_utime;
    int64_t settled_utime;
}
)");
  earlier.finalize();

  beft::hypotheses_t all{};
  all.tick = 12;
  all.hypotheses = {hypothesisNamed("victim_1", 3), hypothesisNamed("radio", 0), hypothesisNamed("a_longer_name", 5)};
  all.num_hypotheses = 3;
  const std::vector<uint8_t> expected = encodedMessage(all);
  std::vector<uint8_t> old = withoutLastByteOfEach(expected, 8 + 8 + 8 + 4, all.hypotheses,
                                                   earlier.fingerprint("beft.hypotheses_t"));
  ASSERT_EQ(old.size(), expected.size() - 3);
  ASSERT_TRUE(upgradeEarlierLayout(old));
  EXPECT_EQ(old, expected);
  EXPECT_FALSE(upgradeEarlierLayout(old));  // today's layout is left as it is

  beft::hypothesis_changes_t changes{};
  changes.tick = 13;
  changes.num_hypotheses = 3;
  changes.changed = {hypothesisNamed("radio", 2)};
  changes.num_changed = 1;
  const std::vector<uint8_t> expected_changes = encodedMessage(changes);
  std::vector<uint8_t> old_changes = withoutLastByteOfEach(expected_changes, 8 + 8 + 8 + 8 + 4 + 4, changes.changed,
                                                           earlier.fingerprint("beft.hypothesis_changes_t"));
  ASSERT_TRUE(upgradeEarlierLayout(old_changes));
  EXPECT_EQ(old_changes, expected_changes);

  // Cut short: not a message of the earlier layout, left for the guard.
  std::vector<uint8_t> cut_old = withoutLastByteOfEach(expected, 8 + 8 + 8 + 4, all.hypotheses,
                                                       earlier.fingerprint("beft.hypotheses_t"));
  cut_old.resize(cut_old.size() - 5);
  const std::vector<uint8_t> cut_old_before = cut_old;
  EXPECT_FALSE(upgradeEarlierLayout(cut_old));
  EXPECT_EQ(cut_old, cut_old_before);
}

// The peek log of the test data, recorded before `located` (and before
// HYPOTHESIS_CHANGES): its AUDIO and HYPOTHESES read as today's types, not
// located.
TEST(EarlierLayouts, TheOldLogsPerceptsAndHypothesesReadAsNotLocated) {
  LogReader log(kOldLog);
  LogEvent event;
  int audio = 0, hypotheses = 0;
  while (log.next(event)) {
    if (event.channel == "AUDIO") {
      beft::acoustic_percepts_t m{};
      ASSERT_TRUE(guardedDecode(event.data.data(), event.data.size(), m).ok());
      for (const auto& p : m.percepts) EXPECT_FALSE(p.located) << p.object_id;
      audio += m.num_percepts;
    } else if (event.channel == "HYPOTHESES") {
      beft::hypotheses_t m{};
      ASSERT_TRUE(guardedDecode(event.data.data(), event.data.size(), m).ok());
      for (const auto& h : m.hypotheses) EXPECT_FALSE(h.located) << h.object_id;
      hypotheses += m.num_hypotheses;
    }
  }
  EXPECT_GT(audio, 0);
  EXPECT_GT(hypotheses, 0);
  EXPECT_FALSE(log.damage().any());
}

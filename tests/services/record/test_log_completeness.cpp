// The recorder's account of its log (RECORD_STATUS): messages written
// without their envelopes as they come (what follows a gap is not held back),
// a gap that is repaired counted as repaired, and a
// message its sender no longer keeps counted as lost, so the log says it is
// not complete. Over a real UDP port, the sender played by hand.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <beft/record_status_t.hpp>
#include <beft/run_status_t.hpp>
#include <beft/sender_state_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/common/lcm_url.hpp"
#include "lib/launch/free_port.hpp"
#include "lib/wire/envelope.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/log_reader.hpp"
#include "services/record/recorded_ports.hpp"
#include "services/record/recorder.hpp"

namespace {

constexpr uint64_t kSender = 0xfeed;

std::vector<uint8_t> statusMessage(int64_t tick, uint64_t sequence) {
  beft::run_status_t status{};
  status.tick = tick;
  status.message = "tick " + std::to_string(tick);
  std::vector<uint8_t> bytes(static_cast<std::size_t>(status.getEncodedSize()));
  status.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  beft::wire::Envelope envelope;
  envelope.sender = kSender;
  envelope.sequence = sequence;
  beft::wire::appendEnvelope(bytes, envelope);
  return bytes;
}

void send(lcm::LCM& lcm, int64_t tick, uint64_t sequence) {
  const auto bytes = statusMessage(tick, sequence);
  lcm.publish("RUN_STATUS", bytes.data(), static_cast<unsigned>(bytes.size()));
}

void announce(lcm::LCM& lcm, int64_t last, int64_t first_kept) {
  beft::sender_state_t state{};
  state.sender = static_cast<int64_t>(kSender);
  state.process = "test";
  state.channels = {"RUN_STATUS"};
  state.last_sequences = {last};
  state.first_kept = {first_kept};
  state.stream_started = {1};  // long ago: the stream is known from its messages
  state.count = 1;
  lcm.publish("BEFT_SENDERS", &state);
}

struct Written {
  std::vector<beft::run_status_t> statuses;
  std::vector<beft::record_status_t> accounts;
};

Written readBack(const std::string& path) {
  Written written;
  beft::wire::LogReader reader(path);
  beft::wire::LogEvent event;
  while (reader.next(event)) {
    if (event.channel == "RUN_STATUS") {
      beft::run_status_t status;
      EXPECT_EQ(beft::wire::payloadSize(event.data.data(), event.data.size()), event.data.size())
          << "an envelope was written into the log";
      EXPECT_TRUE(beft::wire::guardedDecode(event.data.data(), event.data.size(), status).ok());
      written.statuses.push_back(status);
    } else if (event.channel == "RECORD_STATUS") {
      beft::record_status_t account;
      EXPECT_TRUE(beft::wire::guardedDecode(event.data.data(), event.data.size(), account).ok());
      written.accounts.push_back(account);
    }
  }
  return written;
}

class LogCompleteness : public ::testing::Test {
 protected:
  void SetUp() override {
    const int port = beft::launch::findFreeUdpPort(30000, 34999);
    ASSERT_GT(port, 0);
    url_ = beft::lcmUrlForPort(port);
    path_ = (std::filesystem::temp_directory_path() / ("beft_completeness_" + std::to_string(getpid()) + "_" +
                                                       ::testing::UnitTest::GetInstance()->current_test_info()->name()))
                .string();
    std::filesystem::remove(path_);
  }
  void TearDown() override { std::filesystem::remove(path_); }

  std::string url_, path_;
};

TEST_F(LogCompleteness, AGapFilledLaterIsRepairedAndTheLogComplete) {
  lcm::LCM lcm(url_);
  beft::record::RecordOptions options;
  options.path = path_;
  {
    beft::record::Recorder recorder(lcm, url_, options, beft::record::RecordedPorts().taken());
    lcm::LCM sender(url_);
    send(sender, 1, 1);
    send(sender, 3, 3);
    send(sender, 2, 2);  // as a repair would bring it
    announce(sender, 3, 1);
    recorder.drain(50, 3000);
    recorder.writeStatus(true);
  }
  const Written written = readBack(path_);
  // Each once, in the order they came (a log is ordered by time).
  ASSERT_EQ(written.statuses.size(), 3u);
  std::vector<int64_t> ticks;
  for (const auto& status : written.statuses) ticks.push_back(status.tick);
  EXPECT_EQ(ticks, (std::vector<int64_t>{1, 3, 2}));
  ASSERT_EQ(written.accounts.size(), 1u);
  EXPECT_TRUE(written.accounts[0].final);
  EXPECT_TRUE(written.accounts[0].complete);
  EXPECT_EQ(written.accounts[0].lost, 0);
  EXPECT_EQ(written.accounts[0].messages, 3);
}

TEST_F(LogCompleteness, AMessageItsSenderNoLongerKeepsMakesTheLogIncomplete) {
  lcm::LCM lcm(url_);
  beft::record::RecordOptions options;
  options.path = path_;
  {
    beft::record::Recorder recorder(lcm, url_, options, beft::record::RecordedPorts().taken());
    lcm::LCM sender(url_);
    send(sender, 1, 1);
    send(sender, 4, 4);
    announce(sender, 4, 4);  // 2 and 3 are gone
    recorder.drain(50, 3000);
    recorder.writeStatus(true);
  }
  const Written written = readBack(path_);
  ASSERT_EQ(written.statuses.size(), 2u);
  EXPECT_EQ(written.statuses[1].tick, 4);
  ASSERT_EQ(written.accounts.size(), 1u);
  EXPECT_FALSE(written.accounts[0].complete);
  EXPECT_EQ(written.accounts[0].lost, 2);
}

TEST_F(LogCompleteness, ALastMessageAnnouncedButNeverHeardMakesTheLogIncomplete) {
  lcm::LCM lcm(url_);
  beft::record::RecordOptions options;
  options.path = path_;
  {
    beft::record::Recorder recorder(lcm, url_, options, beft::record::RecordedPorts().taken());
    lcm::LCM sender(url_);
    send(sender, 1, 1);
    announce(sender, 2, 1);  // 2 was sent, nobody answers for it
    recorder.drain(50, 300);
    recorder.writeStatus(true);
  }
  const Written written = readBack(path_);
  ASSERT_EQ(written.accounts.size(), 1u);
  EXPECT_FALSE(written.accounts[0].complete);
  EXPECT_EQ(written.accounts[0].lost, 1);
}

}  // namespace

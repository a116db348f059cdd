// Loss repair over real sockets, each test on its own UDP port: a receiver
// asks for what it missed and hands the stream on in order; a sender
// answers a repair request with the very bytes it sent, and says what it
// has sent when it falls quiet.
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include <beft/repair_request_t.hpp>
#include <beft/sender_state_t.hpp>
#include <beft/run_status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/common/lcm_url.hpp"
#include "lib/launch/free_port.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/transport/transport.hpp"
#include "lib/wire/envelope.hpp"
#include "lib/wire/guarded_decode.hpp"

namespace transport = beft::transport;

namespace {

// Everything heard on one channel, as raw bytes, through LCM's own receive path.
class RawListener {
 public:
  RawListener(const std::string& url, const std::string& channel) : lcm_(url) {
    lcm_.subscribeFunction(channel, &RawListener::onMessage, this);
  }
  // Handles messages until `enough` holds or 3 s pass.
  template <typename Enough>
  bool waitFor(Enough enough) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(3);
    while (!enough()) {
      if (std::chrono::steady_clock::now() > end) return false;
      lcm_.handleTimeout(20);
    }
    return true;
  }
  std::vector<std::vector<uint8_t>> heard;

 private:
  static void onMessage(const lcm::ReceiveBuffer* buffer, const std::string&, RawListener* self) {
    const auto* bytes = static_cast<const uint8_t*>(buffer->data);
    self->heard.emplace_back(bytes, bytes + buffer->data_size);
  }
  lcm::LCM lcm_;
};

std::vector<uint8_t> enveloped(const std::string& text, uint64_t sender, uint64_t sequence) {
  beft::run_status_t command{};
  command.utime = static_cast<int64_t>(sequence);
  command.message = text;
  
  std::vector<uint8_t> bytes(static_cast<std::size_t>(command.getEncodedSize()));
  command.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  beft::wire::Envelope envelope;
  envelope.sender = sender;
  envelope.sequence = sequence;
  beft::wire::appendEnvelope(bytes, envelope);
  return bytes;
}

class LossRepair : public ::testing::Test {
 protected:
  void SetUp() override {
    const int port = beft::launch::findFreeUdpPort(38000, 39999);
    ASSERT_GT(port, 0);
    url_ = beft::lcmUrlForPort(port);
  }
  std::string url_;
};

TEST_F(LossRepair, AReceiverAsksForAGapAndHandsTheStreamOnInOrder) {
  lcm::LCM receiving_lcm(url_);
  transport::Selection selection;
  selection.rules.push_back(transport::channelRule("RUN_STATUS"));
  auto receiver = transport::openReceiver(receiving_lcm, url_, selection);
  RawListener requests(url_, "BEFT_REPAIR");
  lcm::LCM sender(url_);
  constexpr uint64_t kSender = 0x5e11de5;
  for (uint64_t sequence : {1, 3, 4}) {
    const auto bytes = enveloped("m" + std::to_string(sequence), kSender, sequence);
    sender.publish("RUN_STATUS", bytes.data(), static_cast<unsigned>(bytes.size()));
  }
  std::vector<std::string> handed;
  const transport::Handler take = [&](const transport::Message& message) {
    beft::run_status_t command;
    ASSERT_TRUE(beft::wire::guardedDecode(message.data, message.size, command).ok()) << "envelope left on";
    handed.push_back(command.message);
  };
  for (int i = 0; i < 50 && handed.size() < 1; ++i) receiver->receive(50, take);
  ASSERT_TRUE(requests.waitFor([&] { return !requests.heard.empty(); })) << "no repair request";
  beft::repair_request_t request;
  ASSERT_TRUE(beft::wire::guardedDecode(requests.heard[0].data(), requests.heard[0].size(), request).ok());
  EXPECT_EQ(static_cast<uint64_t>(request.sender), kSender);
  EXPECT_EQ(request.channel, "RUN_STATUS");
  EXPECT_EQ(request.sequences, (std::vector<int64_t>{2}));
  EXPECT_EQ(handed, (std::vector<std::string>{"m1"})) << "3 and 4 wait behind the gap";

  const auto repair = enveloped("m2", kSender, 2);
  sender.publish("RUN_STATUS", repair.data(), static_cast<unsigned>(repair.size()));
  sender.publish("RUN_STATUS", repair.data(), static_cast<unsigned>(repair.size()));  // a second copy
  for (int i = 0; i < 50 && handed.size() < 4; ++i) receiver->receive(50, take);
  EXPECT_EQ(handed, (std::vector<std::string>{"m1", "m2", "m3", "m4"}));
  EXPECT_EQ(receiver->repairStats().repaired, 1u);
  EXPECT_GE(receiver->repairStats().duplicates, 1u);
}

TEST_F(LossRepair, AReceiverAsksAgainWhileNobodyAnswersWithoutBeingWokenByMessages) {
  lcm::LCM receiving_lcm(url_);
  transport::Selection selection;
  selection.rules.push_back(transport::channelRule("RUN_STATUS"));
  auto receiver = transport::openReceiver(receiving_lcm, url_, selection);
  RawListener requests(url_, "BEFT_REPAIR");
  lcm::LCM sender(url_);
  for (uint64_t sequence : {1, 3}) {
    const auto bytes = enveloped("m", 77, sequence);
    sender.publish("RUN_STATUS", bytes.data(), static_cast<unsigned>(bytes.size()));
  }
  // The process sleeps on fd() alone: the timer inside wakes it to ask again.
  const transport::Handler ignore = [](const transport::Message&) {};
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(400);
  while (std::chrono::steady_clock::now() < end) receiver->receive(50, ignore);
  ASSERT_TRUE(requests.waitFor([&] { return requests.heard.size() >= 3; }))
      << "asked " << requests.heard.size() << " times in 0.4 s";
}

TEST_F(LossRepair, ASenderAnswersARequestWithTheBytesItSentAndSaysWhatItSent) {
  lcm::LCM lcm(url_);
  auto publishing = transport::attachPublisher(lcm, url_, "test_sender");
  RawListener commands(url_, "RUN_STATUS");
  RawListener states(url_, "BEFT_SENDERS");
  for (int i = 1; i <= 3; ++i) {
    beft::run_status_t command{};
    command.utime = i;
    command.message = "c" + std::to_string(i);
    transport::publish(lcm, "RUN_STATUS", command);
  }
  ASSERT_TRUE(commands.waitFor([&] { return commands.heard.size() >= 3; }));
  ASSERT_TRUE(states.waitFor([&] { return !states.heard.empty(); })) << "no state after falling quiet";
  beft::sender_state_t state;
  ASSERT_TRUE(beft::wire::guardedDecode(states.heard[0].data(), states.heard[0].size(), state).ok());
  EXPECT_EQ(static_cast<uint64_t>(state.sender), transport::senderIdOf(lcm));
  ASSERT_EQ(state.channels, (std::vector<std::string>{"RUN_STATUS"}));
  EXPECT_EQ(state.last_sequences[0], 3);
  EXPECT_EQ(state.first_kept[0], 1);

  lcm::LCM asking(url_);
  beft::repair_request_t request{};
  request.sender = static_cast<int64_t>(transport::senderIdOf(lcm));
  request.requester = "test";
  request.channel = "RUN_STATUS";
  request.sequences = {2};
  request.count = 1;
  asking.publish("BEFT_REPAIR", &request);
  ASSERT_TRUE(commands.waitFor([&] { return commands.heard.size() >= 4; })) << "no repair";
  EXPECT_EQ(commands.heard[3], commands.heard[1]) << "a repair is the message, byte for byte";

  request.sender = 12345;  // another sender's request is not this one's business
  asking.publish("BEFT_REPAIR", &request);
  EXPECT_FALSE(commands.waitFor([&] { return commands.heard.size() >= 5; }));
}

TEST_F(LossRepair, PublishedMessagesCarryOneNumberPerChannelFromOne) {
  lcm::LCM lcm(url_);
  RawListener commands(url_, "RUN_STATUS");
  beft::run_status_t command{};
  for (int i = 0; i < 3; ++i) transport::publish(lcm, "RUN_STATUS", command);
  ASSERT_TRUE(commands.waitFor([&] { return commands.heard.size() >= 3; }));
  for (std::size_t i = 0; i < 3; ++i) {
    std::size_t payload = 0;
    beft::wire::Envelope envelope;
    ASSERT_TRUE(beft::wire::splitEnvelope(commands.heard[i].data(), commands.heard[i].size(), payload, envelope));
    EXPECT_EQ(envelope.sequence, i + 1);
    EXPECT_EQ(envelope.sender, transport::senderIdOf(lcm));
    EXPECT_FALSE(envelope.tagged);
  }
}

}  // namespace

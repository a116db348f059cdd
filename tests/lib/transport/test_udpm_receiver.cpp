// The direct udpm receiver against real LCM publishers on a port of its own:
// what the filter lets through arrives whole and in order (fragmented
// messages too), a socket nobody reads keeps what comes, an unfiltered socket
// counts what the kernel drops, and the LCM fallback gives the same messages.
#include "lib/transport/detail/udpm_receiver.hpp"

#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

#include <beft/fire_t.hpp>
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "lib/launch/free_port.hpp"
#include "lib/transport/control_messages.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/transport/transport.hpp"

namespace {

using beft::udpm::Endpoint;
using beft::udpm::Receiver;
using beft::udpm_filter::channelRule;
using beft::udpm_filter::Spec;
using namespace std::chrono_literals;

struct Received {
  std::string channel;
  std::string data;
  int64_t recv_utime;
};

int64_t nowMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::string patterned(std::size_t size, int seed) {
  std::string text(size, '\0');
  for (std::size_t i = 0; i < size; ++i) text[i] = static_cast<char>((i * 7 + static_cast<std::size_t>(seed)) % 253);
  return text;
}

void publish(lcm::LCM& lcm, const std::string& channel, const std::string& data) {
  ASSERT_EQ(lcm.publish(channel, data.data(), static_cast<unsigned>(data.size())), 0) << channel;
}

// Drains `source` until `count` messages came or twenty seconds passed.
template <typename Source>
std::vector<Received> receiveAtLeast(Source& source, std::size_t count) {
  std::vector<Received> got;
  const auto give_up = std::chrono::steady_clock::now() + 20s;
  while (got.size() < count && std::chrono::steady_clock::now() < give_up)
    source.receive(20, [&got](const beft::lcm_wire::Message& m) {
      got.push_back({std::string(m.channel), std::string(reinterpret_cast<const char*>(m.data), m.size), m.recv_utime});
    });
  return got;
}

std::string encodedFire(const std::string& expert) {
  beft::fire_t fire{};
  fire.utime = 1;
  fire.expert = expert;
  fire.transition = "t";
  fire.tick = 1;
  fire.firing_id = 1;
  std::string bytes(static_cast<std::size_t>(fire.getEncodedSize()), '\0');
  fire.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

class UdpmReceiverTest : public ::testing::Test {
 protected:
  void SetUp() override {
    port_ = beft::launch::findFreeUdpPort(35000, 37999);
    ASSERT_GT(port_, 0);
    url_ = beft::lcmUrlForPort(port_);
    endpoint_ = *beft::udpm::parseUrl(url_);
  }
  int port_ = -1;
  std::string url_;
  Endpoint endpoint_;
};

TEST(UdpmUrl, ParsesWhatLcmAccepts) {
  std::string why;
  auto full = beft::udpm::parseUrl("udpm://239.255.76.67:18402?ttl=1&recv_buf_size=8388608", &why);
  ASSERT_TRUE(full) << why;
  EXPECT_EQ(full->group, "239.255.76.67");
  EXPECT_EQ(full->port, 18402);
  EXPECT_EQ(full->ttl, 1);
  EXPECT_EQ(full->recv_buf_size, 8388608);
  auto defaults = beft::udpm::parseUrl("udpm://");
  ASSERT_TRUE(defaults);
  EXPECT_EQ(defaults->group, "239.255.76.67");
  EXPECT_EQ(defaults->port, 7667);
  EXPECT_EQ(defaults->recv_buf_size, 0);
  EXPECT_FALSE(beft::udpm::parseUrl("memq://", &why));
  EXPECT_NE(why.find("udpm"), std::string::npos) << why;
  EXPECT_FALSE(beft::udpm::parseUrl("udpm://10.0.0.1:7667", &why));
  EXPECT_NE(why.find("multicast"), std::string::npos) << why;
  EXPECT_FALSE(beft::udpm::parseUrl("udpm://239.255.76.67:70000", &why));
  EXPECT_NE(why.find("port"), std::string::npos) << why;
  EXPECT_FALSE(beft::udpm::parseUrl("udpm://239.255.76.67:7667?ttl=x", &why));
  EXPECT_NE(why.find("ttl"), std::string::npos) << why;
}

TEST_F(UdpmReceiverTest, ReceivesOnlyWhatItsFilterTakesInOrder) {
  Spec spec;
  spec.rules = {channelRule("KEEP"), channelRule("ALSO")};
  Receiver receiver(endpoint_, spec, 4);
  lcm::LCM sender(url_);
  const int64_t before = nowMicros();
  for (int i = 0; i < 30; ++i) {
    publish(sender, i % 3 == 0 ? "KEEP" : i % 3 == 1 ? "DROP" : "ALSO", "message " + std::to_string(i));
  }
  const auto got = receiveAtLeast(receiver, 20);
  ASSERT_EQ(got.size(), 20u);
  int expected = 0;
  for (const auto& message : got) {
    while (expected % 3 == 1) ++expected;
    EXPECT_EQ(message.channel, expected % 3 == 0 ? "KEEP" : "ALSO");
    EXPECT_EQ(message.data, "message " + std::to_string(expected));
    EXPECT_GE(message.recv_utime, before) << "the kernel's receive time";
    EXPECT_LE(message.recv_utime, nowMicros());
    ++expected;
  }
  EXPECT_EQ(receiver.stats().messages, 20u);
  EXPECT_EQ(receiver.stats().datagrams, 20u) << "the kernel dropped the other channel";
}

TEST_F(UdpmReceiverTest, PutsLcmsFragmentsTogetherAndFiltersTheWholeMessage) {
  Spec spec;
  spec.rules = {channelRule("CAMERA_DEPTH")};
  Receiver receiver(endpoint_, spec);
  lcm::LCM sender(url_);
  const std::string large = patterned(300000, 1), other = patterned(200000, 2);
  publish(sender, "CAMERA_COLOR", other);  // fragments reach the socket; the whole message is refused
  publish(sender, "CAMERA_DEPTH", large);
  publish(sender, "CAMERA_DEPTH", "small");
  const auto got = receiveAtLeast(receiver, 2);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].channel, "CAMERA_DEPTH");
  EXPECT_EQ(got[0].data.size(), large.size());
  EXPECT_TRUE(got[0].data == large);
  EXPECT_EQ(got[1].data, "small");
  // Anything the three above still gave would come before this one.
  publish(sender, "CAMERA_DEPTH", "end");
  const auto more = receiveAtLeast(receiver, 1);
  ASSERT_EQ(more.size(), 1u);
  EXPECT_EQ(more[0].data, "end");
  EXPECT_GT(receiver.stats().datagrams, 7u) << "both large messages came as fragments";
}

TEST_F(UdpmReceiverTest, TakesOnlyItsOwnFirings) {
  Spec spec;
  spec.rules = {beft::control::firesFor("vision")};
  Receiver receiver(endpoint_, spec);
  lcm::LCM sender(url_);
  for (const std::string expert : {"geometry", "vision", "visual_labels", "vision"})
    publish(sender, "FIRE", encodedFire(expert));
  const auto got = receiveAtLeast(receiver, 2);
  ASSERT_EQ(got.size(), 2u);
  for (const auto& message : got) EXPECT_EQ(message.data, encodedFire("vision"));
}

TEST_F(UdpmReceiverTest, ASocketNobodyReadsKeepsWhatComesUntilItIsDrained) {
  Spec spec;
  spec.rules = {channelRule("INPUT")};
  Receiver inputs(endpoint_, spec);
  Receiver witness(endpoint_, spec);  // a datagram reaches every socket of the group at once
  lcm::LCM sender(url_);
  for (int i = 0; i < 300; ++i) publish(sender, "INPUT", patterned(i % 30 == 0 ? 8000 : 300, i));
  ASSERT_EQ(receiveAtLeast(witness, 300).size(), 300u);
  std::vector<std::string> got;
  const int count = inputs.drain([&got](const beft::lcm_wire::Message& m) {
    got.emplace_back(reinterpret_cast<const char*>(m.data), m.size);
  });
  ASSERT_EQ(count, 300) << "one drain takes everything queued, in batches";
  for (int i = 0; i < 300; ++i) EXPECT_TRUE(got[i] == patterned(i % 30 == 0 ? 8000 : 300, i)) << i;
  EXPECT_EQ(inputs.drain([](const beft::lcm_wire::Message&) {}), 0);
}

TEST_F(UdpmReceiverTest, AnUnfilteredSocketCountsWhatTheKernelDropped) {
  Endpoint small = endpoint_;
  small.recv_buf_size = 4096;  // the kernel's floor: a few datagrams
  Spec everything;
  everything.mode = Spec::Mode::RejectListed;
  Receiver recorder(small, everything);
  ASSERT_TRUE(recorder.countsLosses());
  Spec one;
  one.rules = {channelRule("X")};
  EXPECT_FALSE(Receiver(endpoint_, one).countsLosses()) << "a filtered socket's drops include the filtered";
  Receiver witness(endpoint_, one);  // a datagram reaches every socket of the group at once
  lcm::LCM sender(url_);
  const int sent = 200;
  for (int i = 0; i < sent; ++i) publish(sender, "X", patterned(2000, i));
  ASSERT_EQ(receiveAtLeast(witness, sent).size(), static_cast<std::size_t>(sent));
  int got = 0;
  const auto count = [&got](const beft::lcm_wire::Message&) { ++got; };
  recorder.drain(count);
  // The kernel reports its count with the next datagram it queues: one more.
  publish(sender, "X", "the last");
  ASSERT_EQ(receiveAtLeast(witness, 1).size(), 1u);
  recorder.drain(count);
  EXPECT_LT(got, sent);
  EXPECT_GT(recorder.stats().kernel_dropped, 0u);
  EXPECT_EQ(static_cast<uint64_t>(got) + recorder.stats().kernel_dropped, static_cast<uint64_t>(sent + 1))
      << "every datagram is either received or counted as dropped";
}

TEST_F(UdpmReceiverTest, WaitingTimesOutWhenNothingComes) {
  Spec spec;
  spec.rules = {channelRule("NEVER")};
  Receiver receiver(endpoint_, spec);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(receiver.receive(30, [](const beft::lcm_wire::Message&) { ADD_FAILURE(); }), 0);
  EXPECT_GE(std::chrono::steady_clock::now() - start, 25ms);
}

TEST_F(UdpmReceiverTest, TheLcmFallbackDeliversTheSameMessages) {
  Spec spec;
  spec.rules = {channelRule("KEEP"), beft::control::firesFor("dw")};
  for (const bool direct : {true, false}) {
    if (!direct) setenv("BEFT_UDPM_RECEIVER", "0", 1);
    std::string why;
    EXPECT_EQ(beft::transport::directReceiveFor(url_, &why), direct) << why;
    lcm::LCM lcm(url_);
    auto source = beft::transport::openReceiver(lcm, url_, spec);
    EXPECT_NE(source->description().find(direct ? "own receive socket" : "LCM's receive thread"), std::string::npos)
        << source->description();
    lcm::LCM sender(url_);
    publish(sender, "DROP", "d");
    publish(sender, "KEEP", "k1");
    publish(sender, "FIRE", encodedFire("fusion"));
    publish(sender, "FIRE", encodedFire("dw"));
    publish(sender, "KEEP", patterned(150000, 3));
    const auto got = receiveAtLeast(*source, 3);
    ASSERT_EQ(got.size(), 3u) << (direct ? "direct" : "LCM");
    EXPECT_EQ(got[0].data, "k1");
    EXPECT_EQ(got[1].data, encodedFire("dw"));
    EXPECT_TRUE(got[2].data == patterned(150000, 3));
    unsetenv("BEFT_UDPM_RECEIVER");
  }
  lcm::LCM memq("memq://");
  EXPECT_FALSE(beft::transport::directReceiveFor("memq://"));
  auto source = beft::transport::openReceiver(memq, "memq://", spec);
  publish(memq, "KEEP", "over memq");
  publish(memq, "DROP", "not this");
  const auto got = receiveAtLeast(*source, 1);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].data, "over memq");
}

TEST_F(UdpmReceiverTest, SplitReceiversWakeOnOneChannelSetAndQueueTheRest) {
  Spec wake;
  wake.rules = {channelRule("WAKE")};
  Spec queued;  // everything but DROP, as the blackboard stores
  queued.mode = Spec::Mode::RejectListed;
  queued.rules = {channelRule("DROP")};
  for (const bool direct : {true, false}) {
    if (!direct) setenv("BEFT_UDPM_RECEIVER", "0", 1);
    lcm::LCM lcm(url_);
    beft::transport::SplitReceivers sources = beft::transport::openSplitReceivers(lcm, url_, wake, queued);
    ASSERT_TRUE(sources.wake);
    EXPECT_EQ(sources.queued != nullptr, direct) << "LCM's thread: one subscription takes both";
    lcm::LCM sender(url_);
    publish(sender, "DROP", "d");
    publish(sender, "QUEUED", "q");
    publish(sender, "WAKE", "w");
    const auto woke = receiveAtLeast(*sources.wake, direct ? 1 : 2);
    std::vector<std::string> channels;
    for (const auto& m : woke) channels.push_back(m.channel);
    if (direct) {
      EXPECT_EQ(channels, std::vector<std::string>{"WAKE"});
      const auto later = receiveAtLeast(*sources.queued, 1);
      ASSERT_EQ(later.size(), 1u);
      EXPECT_EQ(later[0].channel, "QUEUED") << "neither the dropped nor the waking channel";
    } else {
      EXPECT_EQ(channels, (std::vector<std::string>{"QUEUED", "WAKE"}));
    }
    unsetenv("BEFT_UDPM_RECEIVER");
  }
  lcm::LCM lcm(url_);
  EXPECT_FALSE(beft::transport::openSplitReceivers(lcm, url_, wake, Spec{}).queued) << "nothing to queue: no socket";
  EXPECT_THROW(beft::transport::openSplitReceivers(lcm, url_, queued, wake), std::invalid_argument);
}

TEST(RoomToGather, NeedsTwoMebibytesOfKernelBufferOrLcmsOwnQueue) {
  EXPECT_TRUE(beft::transport::roomToGather(-1));
  EXPECT_TRUE(beft::transport::roomToGather(8 << 20));
  EXPECT_FALSE(beft::transport::roomToGather(416 << 10));
}

TEST_F(UdpmReceiverTest, RefusesWhatItCannotOpenWithTheReason) {
  Endpoint bad = endpoint_;
  bad.group = "not an address";
  try {
    Receiver receiver(bad, Spec{});
    ADD_FAILURE() << "opened";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not an address"), std::string::npos) << e.what();
  }
}

}  // namespace

// The kernel-side channel filter: the compiled BPF program on a real UDP
// socket fed hand-built LCM datagrams, then on a real udpm LCM instance.
#include "lib/transport/detail/udpm_filter.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <beft/fire_t.hpp>
#include <beft/run_status_t.hpp>
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "lib/launch/free_port.hpp"
#include "lib/transport/control_messages.hpp"
#include "lib/common/lcm_url.hpp"

namespace {

using beft::udpm_filter::channelRule;
using beft::udpm_filter::Spec;

// An LCM short message as udpm puts it on the wire.
std::string shortDatagram(const std::string& channel, const std::string& encoded) {
  std::string datagram = "LC02";
  datagram += std::string("\0\0\0\x07", 4);  // sequence number
  datagram += channel;
  datagram.push_back('\0');
  return datagram + encoded;
}

// FIRE and RUN_STATUS as the arbiter writes them (control_messages.hpp).
std::string encodedFire(const std::string& expert) {
  const beft::fire_t fire = beft::control::makeFire(expert, "t_" + expert, 42, 123456789, 99);
  std::string bytes(static_cast<std::size_t>(fire.getEncodedSize()), '\0');
  fire.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

std::string encodedStatus(int8_t state) {
  const beft::run_status_t status = beft::control::makeRunStatus(state, 50, 5000000, "tick 50");
  std::string bytes(static_cast<std::size_t>(status.getEncodedSize()), '\0');
  status.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

// A loopback UDP socket with the filter attached, and a sender to it.
class FilteredSocket {
 public:
  explicit FilteredSocket(const Spec& spec) {
    receiver_ = socket(AF_INET, SOCK_DGRAM, 0);
    sender_ = socket(AF_INET, SOCK_DGRAM, 0);
    address_.sin_family = AF_INET;
    address_.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address_.sin_port = 0;
    bind(receiver_, reinterpret_cast<sockaddr*>(&address_), sizeof(address_));
    socklen_t size = sizeof(address_);
    getsockname(receiver_, reinterpret_cast<sockaddr*>(&address_), &size);
    auto code = beft::udpm_filter::compile(spec);
    sock_fprog program{static_cast<unsigned short>(code.size()), code.data()};
    attached_ = setsockopt(receiver_, SOL_SOCKET, SO_ATTACH_FILTER, &program, sizeof(program)) == 0;
  }
  ~FilteredSocket() {
    close(receiver_);
    close(sender_);
  }
  bool attached() const { return attached_; }

  // Sends the datagram, then a marker that always passes; true if the datagram
  // arrived before the marker.
  bool passes(const std::string& datagram) {
    const std::string marker = "LC03marker";
    sendto(sender_, datagram.data(), datagram.size(), 0, reinterpret_cast<sockaddr*>(&address_), sizeof(address_));
    sendto(sender_, marker.data(), marker.size(), 0, reinterpret_cast<sockaddr*>(&address_), sizeof(address_));
    bool arrived = false;
    for (;;) {
      pollfd poll_fd{receiver_, POLLIN, 0};
      if (poll(&poll_fd, 1, 2000) <= 0) {
        ADD_FAILURE() << "the marker never arrived";
        return arrived;
      }
      std::string buffer(70000, '\0');
      const auto size = recv(receiver_, buffer.data(), buffer.size(), 0);
      buffer.resize(static_cast<std::size_t>(std::max<ssize_t>(size, 0)));
      if (buffer == marker) return arrived;
      arrived = arrived || buffer == datagram;
    }
  }

 private:
  int receiver_ = -1, sender_ = -1;
  sockaddr_in address_{};
  bool attached_ = false;
};

TEST(UdpmFilter, AcceptsOnlyTheListedChannels) {
  Spec spec;
  spec.rules = {channelRule("ROBOT_STATE"), channelRule("A")};
  FilteredSocket socket(spec);
  ASSERT_TRUE(socket.attached());
  EXPECT_TRUE(socket.passes(shortDatagram("ROBOT_STATE", "payload")));
  EXPECT_TRUE(socket.passes(shortDatagram("A", "x")));
  EXPECT_FALSE(socket.passes(shortDatagram("ROBOT_STATES", "payload"))) << "a longer name is another channel";
  EXPECT_FALSE(socket.passes(shortDatagram("ROBOT_STAT", "payload"))) << "a prefix is another channel";
  EXPECT_FALSE(socket.passes(shortDatagram("B", "x")));
  EXPECT_FALSE(socket.passes(shortDatagram("CAMERA_COLOR", std::string(60000, 'c'))));
}

TEST(UdpmFilter, FragmentsAlwaysPassAndForeignDatagramsNever) {
  Spec spec;
  spec.rules = {channelRule("A")};
  FilteredSocket socket(spec);
  ASSERT_TRUE(socket.attached());
  EXPECT_TRUE(socket.passes("LC03" + std::string(30, '\x01')));
  EXPECT_FALSE(socket.passes("hello, not LCM"));
  EXPECT_FALSE(socket.passes("LC0"));
  EXPECT_FALSE(socket.passes(std::string("LC02\0\0\0\x01", 8))) << "a header cut before the channel";
}

TEST(UdpmFilter, FireRuleMatchesTheExpertNameInsideTheRealEncoding) {
  Spec spec;
  spec.rules = {beft::control::firesFor("vision"), channelRule("RUN_STATUS")};
  FilteredSocket socket(spec);
  ASSERT_TRUE(socket.attached());
  EXPECT_TRUE(socket.passes(shortDatagram("FIRE", encodedFire("vision"))));
  EXPECT_FALSE(socket.passes(shortDatagram("FIRE", encodedFire("geometry"))));
  EXPECT_FALSE(socket.passes(shortDatagram("FIRE", encodedFire("visio"))));
  EXPECT_FALSE(socket.passes(shortDatagram("FIRE", encodedFire("vision2"))));
  EXPECT_FALSE(socket.passes(shortDatagram("FIREX", encodedFire("vision"))));
  EXPECT_TRUE(socket.passes(shortDatagram("RUN_STATUS", "s")));
}

TEST(UdpmFilter, RunStatusRuleMatchesTheStateInsideTheRealEncoding) {
  using beft::run_status_t;
  Spec spec;
  spec.rules = {beft::control::runStatusIn(run_status_t::STATE_WAITING, "waiting")};
  FilteredSocket socket(spec);
  ASSERT_TRUE(socket.attached());
  EXPECT_TRUE(socket.passes(shortDatagram("RUN_STATUS", encodedStatus(run_status_t::STATE_WAITING))));
  for (int8_t other : {run_status_t::STATE_RUNNING, run_status_t::STATE_FINISHED, run_status_t::STATE_FAILED}) {
    EXPECT_FALSE(socket.passes(shortDatagram("RUN_STATUS", encodedStatus(other)))) << "state " << int{other};
    const std::string encoded = encodedStatus(other);
    EXPECT_FALSE(beft::udpm_filter::accepts(spec, "RUN_STATUS", encoded.data(), encoded.size()));
  }
}

TEST(UdpmFilter, RejectListedModeDropsOnlyTheListed) {
  Spec spec;
  spec.mode = Spec::Mode::RejectListed;
  spec.rules = {channelRule("FIRE"), channelRule("DONE")};
  FilteredSocket socket(spec);
  ASSERT_TRUE(socket.attached());
  EXPECT_FALSE(socket.passes(shortDatagram("FIRE", encodedFire("vision"))));
  EXPECT_FALSE(socket.passes(shortDatagram("DONE", "d")));
  EXPECT_TRUE(socket.passes(shortDatagram("DONE_NOT", "d")));
  EXPECT_TRUE(socket.passes(shortDatagram("CAMERA_DEPTH", std::string(1000, 'd'))));
}

TEST(UdpmFilter, AcceptsAgreesWithTheKernelProgram) {
  // accepts() judges whole messages where the program cannot (fragments):
  // both must give the same verdict on every short message.
  Spec accept_spec;
  accept_spec.rules = {beft::control::firesFor("vision"), channelRule("RUN_STATUS"), channelRule("A")};
  Spec reject_spec;
  reject_spec.mode = Spec::Mode::RejectListed;
  reject_spec.rules = {channelRule("FIRE"), channelRule("DONE")};
  const std::vector<std::pair<std::string, std::string>> messages = {
      {"FIRE", encodedFire("vision")}, {"FIRE", encodedFire("geometry")}, {"FIRE", encodedFire("vision2")},
      {"FIRE", "short"},               {"RUN_STATUS", "s"},              {"A", ""},
      {"AB", "x"},                     {"DONE", "d"},                    {"CAMERA_DEPTH", std::string(3000, 'd')}};
  for (const Spec* spec : {&accept_spec, &reject_spec}) {
    FilteredSocket socket(*spec);
    ASSERT_TRUE(socket.attached());
    for (const auto& [channel, encoded] : messages)
      EXPECT_EQ(socket.passes(shortDatagram(channel, encoded)),
                beft::udpm_filter::accepts(*spec, channel, encoded.data(), encoded.size()))
          << channel << " (" << encoded.size() << " bytes)";
  }
}

TEST(UdpmFilter, RefusesRulesTooLongToJumpOver) {
  Spec spec;
  spec.rules = {channelRule(std::string(600, 'X'))};
  EXPECT_THROW(beft::udpm_filter::compile(spec), std::invalid_argument);
  spec.rules = {channelRule("")};
  EXPECT_THROW(beft::udpm_filter::compile(spec), std::invalid_argument);
}

TEST(UdpmFilter, ParsesUrlsAndPatterns) {
  EXPECT_EQ(beft::udpm_filter::udpmPort("udpm://239.255.76.67:18402?ttl=0"), 18402);
  EXPECT_EQ(beft::udpm_filter::udpmPort("udpm://239.255.76.67"), 7667);
  EXPECT_EQ(beft::udpm_filter::udpmPort("memq://"), -1);
  EXPECT_TRUE(beft::udpm_filter::isPlainChannel("CAMERA_DEPTH"));
  EXPECT_FALSE(beft::udpm_filter::isPlainChannel(".*"));
  EXPECT_FALSE(beft::udpm_filter::isPlainChannel("BB_.*"));
  EXPECT_FALSE(beft::udpm_filter::isPlainChannel(""));
}

struct Counter {
  std::multiset<std::string> channels;
  void on(const lcm::ReceiveBuffer*, const std::string& channel) { channels.insert(channel); }
};

TEST(UdpmFilter, AnUdpmLcmInstanceStopsReceivingWhatTheFilterDrops) {
  const int port = beft::launch::findFreeUdpPort(23000, 29999);
  ASSERT_GT(port, 0);
  const std::string url = beft::lcmUrlForPort(port);
  lcm::LCM receiver(url), sender(url);
  ASSERT_TRUE(receiver.good());
  Counter counter;
  receiver.subscribe("KEEP", &Counter::on, &counter);
  receiver.subscribe("DROP", &Counter::on, &counter);
  Spec spec;
  spec.rules = {channelRule("KEEP")};
  std::string why;
  ASSERT_TRUE(beft::udpm_filter::install(receiver, url, spec, &why)) << why;
  const uint8_t byte = 1;
  for (int i = 0; i < 5; ++i) {
    sender.publish("DROP", &byte, 1);
    sender.publish("KEEP", &byte, 1);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (counter.channels.count("KEEP") < 5 && std::chrono::steady_clock::now() < deadline) receiver.handleTimeout(100);
  while (receiver.handleTimeout(100) > 0) {
  }
  EXPECT_EQ(counter.channels.count("KEEP"), 5u);
  EXPECT_EQ(counter.channels.count("DROP"), 0u) << "the subscribed but filtered channel reached LCM";
}

TEST(UdpmFilter, InstallSaysWhyItDidNot) {
  lcm::LCM memq("memq://");
  std::string why;
  EXPECT_FALSE(beft::udpm_filter::install(memq, "memq://", Spec{}, &why));
  EXPECT_NE(why.find("udpm"), std::string::npos) << why;

  const int port = beft::launch::findFreeUdpPort(23000, 29999);
  const std::string url = beft::lcmUrlForPort(port);
  lcm::LCM udpm(url);
  setenv("BEFT_UDPM_FILTER", "0", 1);
  EXPECT_FALSE(beft::udpm_filter::install(udpm, url, Spec{}, &why));
  EXPECT_NE(why.find("BEFT_UDPM_FILTER"), std::string::npos) << why;
  unsetenv("BEFT_UDPM_FILTER");
}

}  // namespace

// The bridge's batched reads (services/bridge/gathered_reads.hpp) over a
// datagram socket pair: while messages keep coming, it reads them in a few
// batches, every one of them in order; off (0 ms, or while an external
// expert is connected) it reads each as it comes; a quiet socket costs no
// read at all.
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include "services/bridge/gathered_reads.hpp"

namespace beft::bridge {
namespace {

// A receiver of the datagrams written to the other end of a socket pair.
class PairReceiver : public transport::Receiver {
 public:
  PairReceiver() {
    if (::socketpair(AF_UNIX, SOCK_DGRAM | SOCK_NONBLOCK, 0, ends_) != 0) ADD_FAILURE() << "socketpair";
  }
  ~PairReceiver() override {
    ::close(ends_[0]);
    ::close(ends_[1]);
  }
  int fd() const override { return ends_[0]; }
  int drain(const transport::Handler& handler) override {
    int count = 0;
    char buffer[256];
    for (ssize_t n; (n = ::recv(ends_[0], buffer, sizeof(buffer), 0)) > 0; ++count) {
      transport::Message message;
      message.channel = "TEST";
      message.data = reinterpret_cast<const uint8_t*>(buffer);
      message.size = static_cast<std::size_t>(n);
      handler(message);
    }
    return count;
  }
  std::string description() const override { return "a socket pair"; }
  void send(const std::string& text) { ASSERT_EQ(::send(ends_[1], text.data(), text.size(), 0), ssize_t(text.size())); }

 private:
  int ends_[2] = {-1, -1};
};

struct Outcome {
  std::vector<std::string> received;
  uint64_t reads = 0;
  long wake_ups = 0;  // of the reading thread: its voluntary context switches meanwhile
};

long voluntarySwitchesOfThisThread() {
  rusage usage{};
  getrusage(RUSAGE_THREAD, &usage);
  return usage.ru_nvcsw;
}

// Sends `count` messages one every `every`, on the io_context's thread, then runs on for `after`.
Outcome sendAndRead(int batch_ms, bool gather_now, int count, std::chrono::microseconds every,
                    std::chrono::milliseconds after = std::chrono::milliseconds(100)) {
  boost::asio::io_context io;
  PairReceiver receiver;
  Outcome outcome;
  GatheredReads reads(
      io, receiver,
      [&](const transport::Message& m) {
        outcome.received.emplace_back(reinterpret_cast<const char*>(m.data), m.size);
      },
      batch_ms, [&] { return gather_now; });
  reads.start();
  const long switches_before = voluntarySwitchesOfThisThread();
  std::thread sender([&] {
    for (int i = 0; i < count; ++i) {
      receiver.send("message " + std::to_string(i));
      std::this_thread::sleep_for(every);
    }
  });
  const auto until = std::chrono::steady_clock::now() + every * count + after;
  while (std::chrono::steady_clock::now() < until) io.run_for(std::chrono::milliseconds(10));
  sender.join();
  outcome.wake_ups = voluntarySwitchesOfThisThread() - switches_before;
  io.run_for(after);
  outcome.reads = reads.wakeUps();
  return outcome;
}

std::vector<std::string> expected(int count) {
  std::vector<std::string> texts;
  for (int i = 0; i < count; ++i) texts.push_back("message " + std::to_string(i));
  return texts;
}

TEST(GatheredReads, MessagesThatKeepComingAreReadInAFewBatchesEveryOneInOrder) {
  // 200 messages over about 200 ms: read every 20 ms, that is a dozen reads or so, not 200.
  const Outcome gathered = sendAndRead(20, true, 200, std::chrono::microseconds(1000));
  EXPECT_EQ(gathered.received, expected(200));
  EXPECT_LE(gathered.reads, 40u) << "a read per message or close to it";
  EXPECT_GE(gathered.reads, 3u);
  // Not woken by the messages in between either (a socket asio watches would wake it for each):
  // the reads, their gathering timers and the loop's own 10 ms turns.
  EXPECT_LE(gathered.wake_ups, 110) << gathered.reads << " reads";
}

TEST(GatheredReads, OffOrWhileItShouldNotGatherEachMessageIsReadAsItComes) {
  for (const auto& [batch_ms, gather_now] : {std::pair{0, true}, std::pair{20, false}}) {
    const Outcome each = sendAndRead(batch_ms, gather_now, 50, std::chrono::microseconds(2000));
    EXPECT_EQ(each.received, expected(50)) << batch_ms << " ms, gather " << gather_now;
    EXPECT_GE(each.reads, 40u) << batch_ms << " ms, gather " << gather_now << ": read in batches";
  }
}

TEST(GatheredReads, AQuietSocketCostsNoReadAndTheFirstMessageIsReadAtOnce) {
  boost::asio::io_context io;
  PairReceiver receiver;
  std::vector<std::string> received;
  GatheredReads reads(
      io, receiver,
      [&](const transport::Message& m) { received.emplace_back(reinterpret_cast<const char*>(m.data), m.size); }, 50,
      [] { return true; });
  reads.start();
  io.run_for(std::chrono::milliseconds(100));
  EXPECT_EQ(reads.wakeUps(), 0u);
  receiver.send("first");
  const auto sent = std::chrono::steady_clock::now();
  while (received.empty() && std::chrono::steady_clock::now() - sent < std::chrono::seconds(2))
    io.run_for(std::chrono::milliseconds(1));
  EXPECT_EQ(received, std::vector<std::string>{"first"});
  EXPECT_LT(std::chrono::steady_clock::now() - sent, std::chrono::milliseconds(40)) << "the first message gathered";
}

}  // namespace
}  // namespace beft::bridge

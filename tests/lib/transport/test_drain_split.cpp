// One pass over a split pair: an input that arrives while the wake receiver
// is drained (published just before the FIRE it brings) is handed over in
// the same pass, before the FIRE is served.
#include <deque>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lib/transport/transport.hpp"

namespace {

using beft::transport::Handler;
using beft::transport::Message;

// A receiver whose waiting messages the test scripts; `during_drain` runs
// inside drain(), before the waiting messages are handed over.
class ScriptedReceiver : public beft::transport::Receiver {
 public:
  int fd() const override { return -1; }
  int drain(const Handler& handler) override {
    if (during_drain) {
      auto once = std::move(during_drain);
      during_drain = nullptr;
      once();
    }
    if (fail) return -1;
    int count = 0;
    while (!waiting.empty()) {
      const std::string channel = waiting.front();
      waiting.pop_front();
      Message message{};
      message.channel = channel;
      handler(message);
      ++count;
    }
    return count;
  }
  std::string description() const override { return "scripted"; }

  std::deque<std::string> waiting;
  std::function<void()> during_drain;
  bool fail = false;
};

}  // namespace

TEST(DrainSplit, AnInputArrivingWhileTheFireIsReadIsHandedOverInTheSamePass) {
  ScriptedReceiver control, inputs;
  inputs.waiting = {"ROBOT_STATE"};
  // The command and the FIRE after it arrive after the inputs were drained once.
  control.during_drain = [&] {
    inputs.waiting.push_back("TASK_COMMAND");
    control.waiting.push_back("FIRE");
  };
  std::vector<std::string> order;
  const int count = beft::transport::drainSplit(control, &inputs, [&](const Message& m) { order.emplace_back(m.channel); });
  EXPECT_EQ(count, 3);
  EXPECT_EQ(order, (std::vector<std::string>{"ROBOT_STATE", "FIRE", "TASK_COMMAND"}));
  EXPECT_TRUE(inputs.waiting.empty());
}

TEST(DrainSplit, WithoutAQueuedReceiverDrainsTheWakeOneAndReportsFailure) {
  ScriptedReceiver control;
  control.waiting = {"FIRE", "RUN_STATUS"};
  int seen = 0;
  EXPECT_EQ(beft::transport::drainSplit(control, nullptr, [&](const Message&) { ++seen; }), 2);
  EXPECT_EQ(seen, 2);
  ScriptedReceiver inputs;
  inputs.fail = true;
  EXPECT_EQ(beft::transport::drainSplit(control, &inputs, [&](const Message&) { ++seen; }), -1);
}

// The hub in process: a subscription with throttleMs (BEFT's extension of
// subscribe) is sent at most one message per interval, the newest, and one
// without it every message, as any Foxglove client expects.
#include <chrono>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <beft/robot_state_t.hpp>

#include "lib/common/channels.hpp"
#include "services/bridge/foxglove_hub.hpp"

namespace beft::bridge {
namespace {

using nlohmann::json;

class RefusingControls : public ControlSink {
 public:
  std::string runControl(const RunControlRequest&) override { return "not in this test"; }
  std::string task(const TaskRequest&) override { return "not in this test"; }
  std::string playback(const PlaybackRequest&) override { return "not in this test"; }
};

constexpr uint32_t kViewer = 1;

class ThrottledHub : public ::testing::Test {
 protected:
  RefusingControls controls;
  FoxgloveHub hub{HubOptions{}, controls};

  void SetUp() override {
    hub.onOpen(ClientInfo{kViewer, "127.0.0.1:50000", true, false});
    drain();  // serverInfo and advertise
  }

  uint32_t channelId(const std::string& topic) const {
    for (const auto& channel : hub.channels())
      if (channel.topic == topic) return channel.id;
    ADD_FAILURE() << "no channel " << topic;
    return 0;
  }

  void publishTick(int64_t tick) {
    beft::robot_state_t state{};
    state.utime = tick * 100000;
    state.tick = tick;
    std::vector<uint8_t> bytes(static_cast<std::size_t>(state.getEncodedSize()));
    state.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    hub.onRunMessage(channels::kRobotState, bytes.data(), bytes.size(), static_cast<uint64_t>(tick));
  }

  // The ticks of the ROBOT_STATE data frames waiting for the viewer, by subscription id.
  std::vector<std::pair<uint32_t, int64_t>> drain() {
    std::vector<std::pair<uint32_t, int64_t>> ticks;
    OutgoingFrame frame;
    while (hub.nextFrame(kViewer, frame)) {
      if (frame.text || frame.bytes.size() < 13) continue;
      uint32_t subscription = 0;
      for (int i = 0; i < 4; ++i) subscription |= uint32_t{static_cast<uint8_t>(frame.bytes[1 + i])} << (8 * i);
      ticks.emplace_back(subscription, json::parse(frame.bytes.substr(13)).at("tick").get<int64_t>());
    }
    return ticks;
  }
};

TEST_F(ThrottledHub, AThrottledSubscriptionGetsTheFirstThenOnlyTheNewestWhenItsTimeIsUp) {
  hub.onText(kViewer, json{{"op", "subscribe"},
                           {"subscriptions", {{{"id", 7}, {"channelId", channelId("ROBOT_STATE")}, {"throttleMs", 10000}}}}}
                          .dump());
  for (int64_t tick = 1; tick <= 5; ++tick) publishTick(tick);
  EXPECT_EQ(drain(), (std::vector<std::pair<uint32_t, int64_t>>{{7, 1}}));

  hub.sendThrottled(std::chrono::steady_clock::now());  // 10 s are not up: 5 stays held
  EXPECT_TRUE(drain().empty());
  hub.sendThrottled(std::chrono::steady_clock::now() + std::chrono::seconds(11));
  EXPECT_EQ(drain(), (std::vector<std::pair<uint32_t, int64_t>>{{7, 5}}));
  hub.sendThrottled(std::chrono::steady_clock::now() + std::chrono::seconds(60));  // nothing held: nothing again
  EXPECT_TRUE(drain().empty());
}

TEST_F(ThrottledHub, WithoutThrottleEveryMessageAndUnsubscribingDropsWhatWasHeld) {
  hub.onText(kViewer, json{{"op", "subscribe"},
                           {"subscriptions", {{{"id", 3}, {"channelId", channelId("ROBOT_STATE")}}}}}
                          .dump());
  for (int64_t tick = 1; tick <= 5; ++tick) publishTick(tick);
  EXPECT_EQ(drain().size(), 5u);

  hub.onText(kViewer, json{{"op", "unsubscribe"}, {"subscriptionIds", {3}}}.dump());
  hub.onText(kViewer, json{{"op", "subscribe"},
                           {"subscriptions", {{{"id", 4}, {"channelId", channelId("ROBOT_STATE")}, {"throttleMs", 5000}}}}}
                          .dump());
  const auto kept = drain();  // the newest message, sent to a new subscriber at once
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].second, 5);
  publishTick(6);  // sent: the throttle starts with the first message
  publishTick(7);  // held
  EXPECT_EQ(drain(), (std::vector<std::pair<uint32_t, int64_t>>{{4, 6}}));
  hub.onText(kViewer, json{{"op", "unsubscribe"}, {"subscriptionIds", {4}}}.dump());
  hub.sendThrottled(std::chrono::steady_clock::now() + std::chrono::seconds(60));
  EXPECT_TRUE(drain().empty());
}

}  // namespace
}  // namespace beft::bridge

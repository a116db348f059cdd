// The hub in process: a subscription with throttleMs (BEFT's extension of
// subscribe) is sent at most one message per interval, the newest, and one
// without it every message, as any Foxglove client expects; a viewer's data
// frames leave in bursts at flush(), an external expert's at once; the
// processes' log lines on /log and the arbiter's firing trace on /firings.
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <beft/robot_state_t.hpp>

#include "lib/common/channels.hpp"
#include "services/bridge/external_experts.hpp"
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

// Counts what the hub asks of the server.
class RecordingSockets : public ClientSockets {
 public:
  void wake(uint32_t client) override { ++wakes[client]; }
  void drop(uint32_t client) override { ++drops[client]; }
  std::map<uint32_t, int> wakes, drops;
};

// An external expert's messages would go on the bus; nothing is published here.
class SilentBus : public ExpertBus {
 public:
  std::string publish(const std::string&, const std::vector<uint8_t>&) override { return ""; }
  void listPublished(beft::done_t&) override {}
};

class ThrottledHub : public ::testing::Test {
 protected:
  RefusingControls controls;
  FoxgloveHub hub{HubOptions{}, controls};

  void SetUp() override {
    hub.onOpen(ClientInfo{kViewer, "127.0.0.1:50000", true, false});
    drain();  // serverInfo and advertise
  }

  void subscribe(uint32_t client, uint32_t subscription, const std::string& topic, int throttle_ms = 0) {
    json wanted = {{"id", subscription}, {"channelId", channelId(topic)}};
    if (throttle_ms > 0) wanted["throttleMs"] = throttle_ms;
    hub.onText(client, json{{"op", "subscribe"}, {"subscriptions", {wanted}}}.dump());
  }

  // The text of the foxglove.Log messages waiting for `client` on `subscription`.
  std::vector<std::string> logTexts(uint32_t client, uint32_t subscription) {
    std::vector<std::string> texts;
    OutgoingFrame frame;
    while (hub.nextFrame(client, frame)) {
      if (frame.text || frame.bytes.size() < 13) continue;
      uint32_t id = 0;
      for (int i = 0; i < 4; ++i) id |= uint32_t{static_cast<uint8_t>(frame.bytes[1 + i])} << (8 * i);
      if (id == subscription) texts.push_back(json::parse(frame.bytes.substr(13)).at("message").get<std::string>());
    }
    return texts;
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

// The run sends a viewer a message every millisecond or so at full speed:
// its data frames wait for flush() and leave together (the socket is woken
// once for them), while answers to what it asked go at once.
TEST_F(ThrottledHub, AViewersDataFramesWaitForTheFlushAndAnswersDoNot) {
  RecordingSockets sockets;
  hub.attach(sockets);
  subscribe(kViewer, 3, "ROBOT_STATE");
  const int after_subscribing = sockets.wakes[kViewer];  // the newest message, if any, sent at once
  for (int64_t tick = 1; tick <= 4; ++tick) publishTick(tick);
  EXPECT_EQ(sockets.wakes[kViewer], after_subscribing) << "woken before the flush";
  hub.flush();
  EXPECT_EQ(sockets.wakes[kViewer], after_subscribing + 1);
  hub.flush();  // nothing new: not woken again
  EXPECT_EQ(sockets.wakes[kViewer], after_subscribing + 1);
  EXPECT_EQ(drain().size(), 4u) << "every message is sent all the same";

  hub.onText(kViewer, R"({"op": "subscribe", "subscriptions": [{"id": 9, "channelId": 99999}]})");
  EXPECT_EQ(sockets.wakes[kViewer], after_subscribing + 2) << "an answer (a status) waits for no flush";
}

// An external expert is a link of the lockstep chain: what it reads leaves at once.
TEST_F(ThrottledHub, AnExternalExpertsFramesLeaveAtOnce) {
  SilentBus bus;
  ExternalExperts experts(bus);
  hub.acceptExperts(experts);
  RecordingSockets sockets;
  hub.attach(sockets);
  constexpr uint32_t kExpert = 2;
  hub.onOpen(ClientInfo{kExpert, "127.0.0.1:50001", true, false});
  hub.onText(kExpert, json{{"op", "advertise"},
                           {"channels", {{{"id", 1}, {"topic", kExpertTopic}, {"encoding", "json"},
                                          {"schemaName", kExpertSchema}}}}}
                          .dump());
  const std::string announcement =
      R"({"protocol": 1, "name": "dw", "pid": 1, "host": "h",
          "reads": [{"channel": "ROBOT_STATE", "type": "beft.robot_state_t"}],
          "writes": [{"channel": "DYNAMIC_WEIGHTS", "type": "beft.dynamic_weights_t"}],
          "parameters": [], "resume_log": ""})";
  std::string publish(5, '\0');
  publish[0] = 1;  // opcode: client message data
  publish[1] = 1;  // on client channel 1 (little-endian uint32)
  hub.onBinary(kExpert, publish + announcement);
  ASSERT_EQ(experts.nameOf(kExpert), "dw");
  subscribe(kExpert, 4, "ROBOT_STATE");
  subscribe(kViewer, 3, "ROBOT_STATE");
  const int expert_before = sockets.wakes[kExpert], viewer_before = sockets.wakes[kViewer];
  publishTick(1);
  EXPECT_EQ(sockets.wakes[kExpert], expert_before + 1);
  EXPECT_EQ(sockets.wakes[kViewer], viewer_before) << "the viewer waits for the flush";
}

// At full speed nearly every line of processes.log is the arbiter's trace
// (ten a tick): it has a topic of its own, and a firing that went wrong is
// on /log as well.
TEST_F(ThrottledHub, TheArbitersFiringTraceIsOnFiringsAndEveryOtherLineOnLog) {
  subscribe(kViewer, 1, kLogTopic);
  subscribe(kViewer, 2, kFiringsTopic);
  hub.publishLogLines({"[arbiter] tick     3  firing     31  vision           ok           0.410 ms",
                       "[vision] [vision] WARN: the camera frame came late",
                       "[arbiter] tick     3  firing     32  fusion           timeout      5.000 ms  -> retry: no DONE",
                       "[arbiter] [arbiter] info: stopping after 300 ticks"},
                      1000);
  EXPECT_EQ(logTexts(kViewer, 1),
            (std::vector<std::string>{"[vision] WARN: the camera frame came late",
                                      "tick     3  firing     32  fusion           timeout      5.000 ms  -> retry: no DONE",
                                      "[arbiter] info: stopping after 300 ticks"}));
  hub.publishLogLines({"[arbiter] tick     4  firing     41  world            ok           1.000 ms"}, 2000);
  EXPECT_EQ(logTexts(kViewer, 2),
            (std::vector<std::string>{"tick     4  firing     41  world            ok           1.000 ms"}));
}

// A viewer that shows only the newest firing asks /firings with throttleMs:
// it gets the newest line when its time is up, not the ones in between.
TEST_F(ThrottledHub, AThrottledFiringsSubscriptionGetsOnlyTheNewestLine) {
  subscribe(kViewer, 2, kFiringsTopic, 10000);
  for (int firing = 1; firing <= 5; ++firing)
    hub.publishLogLines({"[arbiter] tick     1  firing      " + std::to_string(firing) + "  world  ok  1.0 ms"}, 1000);
  EXPECT_EQ(logTexts(kViewer, 2), (std::vector<std::string>{"tick     1  firing      1  world  ok  1.0 ms"}));
  hub.sendThrottled(std::chrono::steady_clock::now() + std::chrono::seconds(11));
  EXPECT_EQ(logTexts(kViewer, 2), (std::vector<std::string>{"tick     1  firing      5  world  ok  1.0 ms"}));
}

}  // namespace
}  // namespace beft::bridge

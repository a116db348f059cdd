// beft-bridge as a program, against a minimal WebSocket client: what it
// tells a client, subscriptions, untrusted frames, many clients, the page's
// files, and who may send controls. On a stored log (nothing else running)
// or on an LCM port of the test's own that the test feeds.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <set>

#include "tests/services/bridge/bridge_client.hpp"

using namespace beft::bridge_test;
using nlohmann::json;

namespace {

const std::string kLog = std::string(BEFT_SOURCE_DIR) + "/tests/system/data/peek_6_ticks.lcmlog";

// The id of an advertised channel by topic.
uint32_t channelId(const json& advertise, const std::string& topic) {
  for (const auto& channel : advertise["channels"])
    if (channel["topic"] == topic) return channel["id"].get<uint32_t>();
  ADD_FAILURE() << topic << " not advertised";
  return 0;
}

// A client that has read serverInfo and advertise.
struct Viewer {
  explicit Viewer(int port, const std::string& target = "/", const std::string& address = "127.0.0.1",
                  const std::string& local = "")
      : client(address, port, target, local) {
    info = client.readOp("serverInfo");
    advertise = client.readOp("advertise");
  }
  void subscribe(uint32_t subscription, const std::string& topic) {
    client.sendJson(json{{"op", "subscribe"}, {"subscriptions", {{{"id", subscription}, {"channelId", channelId(advertise, topic)}}}}});
  }
  WsClient client;
  json info, advertise;
};

class LogBridge : public ::testing::Test {
 protected:
  void SetUp() override {
    web_ = std::filesystem::temp_directory_path() / ("beft_bridge_web_" + std::to_string(getpid()));
    std::filesystem::create_directories(web_);
    std::ofstream(web_ / "index.html") << "<html>viewer</html>";
    std::ofstream(web_.parent_path() / ("beft_bridge_secret_" + std::to_string(getpid()))) << "secret";
    bridge_ = std::make_unique<BridgeProgram>(
        std::vector<std::string>{"--log", kLog, "--paused", "--web-dir", web_.string(), "--lcm-url", "memq://"});
    ASSERT_TRUE(bridge_->listening()) << bridge_->output();
  }
  void TearDown() override {
    if (bridge_) {
      EXPECT_EQ(bridge_->stop(), 0) << bridge_->output();
    }
    std::filesystem::remove_all(web_);
    std::filesystem::remove(web_.parent_path() / ("beft_bridge_secret_" + std::to_string(getpid())));
  }
  std::filesystem::path web_;
  std::unique_ptr<BridgeProgram> bridge_;
};

}  // namespace

TEST_F(LogBridge, TellsServerInfoAndAdvertisesEveryTopic) {
  Viewer viewer(bridge_->port());
  EXPECT_EQ(viewer.client.subprotocol(), "foxglove.websocket.v1");
  EXPECT_EQ(viewer.info["name"], "beft-bridge");
  const std::set<std::string> capabilities(viewer.info["capabilities"].begin(), viewer.info["capabilities"].end());
  EXPECT_TRUE(capabilities.count("clientPublish"));
  EXPECT_TRUE(capabilities.count("time"));
  EXPECT_FALSE(viewer.info["sessionId"].get<std::string>().empty());
  EXPECT_EQ(viewer.info["metadata"]["mode"], "log");
  std::set<std::string> topics;
  for (const auto& channel : viewer.advertise["channels"]) {
    topics.insert(channel["topic"].get<std::string>());
    EXPECT_EQ(channel["encoding"], "json");
    EXPECT_EQ(channel["schemaEncoding"], "jsonschema");
    EXPECT_EQ(json::parse(channel["schema"].get<std::string>())["type"], "object") << channel["topic"];
  }
  for (const char* topic : {"ROBOT_STATE", "GT_OBJECTS", "CAMERA_COLOR", "TASK_STACK", "RUN_CONTROL_STATE", "/scene",
                            "/tf", "/obstacle_map", "/camera/color", "/camera/depth", "/log"})
    EXPECT_TRUE(topics.count(topic)) << topic;
}

TEST_F(LogBridge, SubscriptionsGetTheirDataUntilUnsubscribed) {
  Viewer viewer(bridge_->port());
  viewer.subscribe(7, "ROBOT_STATE");
  viewer.client.advertise(1, "/beft/playback");
  viewer.client.publish(1, {{"action", "play"}, {"speed", 5}});
  const MessageData first = viewer.client.readData(7);
  const json robot = json::parse(first.payload);
  EXPECT_TRUE(robot.contains("tick"));
  EXPECT_TRUE(robot["x"].is_number());
  EXPECT_GT(first.time_ns, 0u);
  // Unsubscribed, then a marker: an answer to a bad request comes after everything queued before it.
  viewer.client.sendJson(json{{"op", "unsubscribe"}, {"subscriptionIds", {7}}});
  viewer.client.sendText("not json");
  viewer.client.readOp("status");
  viewer.subscribe(8, "/tf");  // made of the same robot states: shows that playback went on
  viewer.client.publish(1, {{"action", "seek"}, {"time_ns", 0}});
  viewer.client.publish(1, {{"action", "play"}, {"speed", 1}});
  std::vector<Frame> after;
  for (int transforms = 0; transforms < 2;) {  // the one in force when subscribed, then one played
    after.push_back(viewer.client.read());
    MessageData data;
    if (parseMessageData(after.back(), data) && data.subscription == 8) ++transforms;
  }
  for (const auto& frame : after) {
    MessageData data;
    if (parseMessageData(frame, data)) {
      EXPECT_NE(data.subscription, 7u);
    }
  }
}

TEST_F(LogBridge, AnswersGarbageWithStatusAndServesOn) {
  Viewer viewer(bridge_->port());
  const std::vector<std::pair<bool, std::string>> garbage = {
      {true, "{"},
      {true, "[]"},
      {true, R"({"op":"fly"})"},
      {true, R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":99999}]})"},
      {true, R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":1}]})"},
      {true, R"({"op":"advertise","channels":[{"id":1,"topic":"/elsewhere","encoding":"json","schemaName":"x"}]})"},
      {false, std::string("\x07\x01\x02", 3)},
      {false, std::string("\x01\x09\x00\x00\x00{}", 7)},  // a channel never advertised
      {false, ""}};
  for (const auto& [text, bytes] : garbage) {
    if (text) viewer.client.sendText(bytes);
    else viewer.client.sendBinary(bytes);
    const json status = viewer.client.readOp("status");
    EXPECT_GE(status["level"].get<int>(), 1) << bytes;
    EXPECT_FALSE(status["message"].get<std::string>().empty());
  }
  // A frame over the bound ends that connection; the bridge serves on.
  bool closed = false;
  try {
    viewer.client.sendText(std::string((std::size_t{1} << 20) + 100, ' '));
    for (int i = 0; i < 1000; ++i) viewer.client.read();
  } catch (const std::exception&) {
    closed = true;
  }
  EXPECT_TRUE(closed);
  Viewer again(bridge_->port());
  again.subscribe(1, "GT_OBJECTS");
  again.client.advertise(2, "/beft/playback");
  again.client.publish(2, {{"action", "play"}, {"speed", 5}});
  EXPECT_TRUE(json::parse(again.client.readData(1).payload).contains("objects"));
}

TEST_F(LogBridge, ServesTwentyClientsAtOnce) {
  std::vector<std::unique_ptr<Viewer>> viewers;
  for (int i = 0; i < 20; ++i) {
    viewers.push_back(std::make_unique<Viewer>(bridge_->port()));
    viewers.back()->subscribe(3, "/scene");
  }
  viewers.front()->client.advertise(1, "/beft/playback");
  viewers.front()->client.publish(1, {{"action", "play"}, {"speed", 2}});
  for (auto& viewer : viewers) {
    const json scene = json::parse(viewer->client.readData(3).payload);
    EXPECT_TRUE(scene.contains("entities"));
  }
}

TEST_F(LogBridge, ServesThePageAndNothingOutsideIt) {
  const HttpReply page = httpGet(bridge_->port(), "/");
  EXPECT_EQ(page.status, 200);
  EXPECT_EQ(page.body, "<html>viewer</html>");
  EXPECT_EQ(page.content_type, "text/html; charset=utf-8");
  const std::string secret = "beft_bridge_secret_" + std::to_string(getpid());
  EXPECT_EQ(httpGet(bridge_->port(), "/../" + secret).status, 404);
  EXPECT_EQ(httpGet(bridge_->port(), "/%2e%2e/" + secret).status, 404);
  EXPECT_EQ(httpGet(bridge_->port(), "/nothing.js").status, 404);
}

// The run's net drawn for the page, with every place and transition named
// (the page lights them), and the processes' log lines kept for a viewer
// that connects after they were written.
TEST(NetAndLogBridge, ServesTheNetDrawnAndTheLogLinesToALateViewer) {
  const auto dir = std::filesystem::temp_directory_path() / ("beft_bridge_net_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string processes_log = (dir / "processes.log").string();
  std::ofstream(processes_log) << "[arbiter] [arbiter] info: first line\n[vision] [vision] WARN: second line\n";
  const std::string net = std::string(BEFT_SOURCE_DIR) + "/scenarios/nets/default.pnml";
  BridgeProgram bridge({"--log", kLog, "--paused", "--net", net, "--log-file", processes_log, "--lcm-url", "memq://"});
  ASSERT_TRUE(bridge.listening()) << bridge.output();
  usleep(600 * 1000);  // the log file is read every 250 ms, before any viewer comes
  Viewer viewer(bridge.port());
  EXPECT_EQ(viewer.info["metadata"]["net"], "/net.svg");
  const HttpReply drawing = httpGet(bridge.port(), "/net.svg");
  EXPECT_EQ(drawing.status, 200);
  EXPECT_EQ(drawing.content_type, "image/svg+xml");
  EXPECT_NE(drawing.body.find("<svg"), std::string::npos);
  EXPECT_NE(drawing.body.find("id=\"place:p_tick_start\""), std::string::npos) << drawing.body.substr(0, 400);
  EXPECT_NE(drawing.body.find("transition expert&#45;vision"), std::string::npos);
  viewer.subscribe(3, "/log");
  const json first = json::parse(viewer.client.readData(3).payload);
  const json second = json::parse(viewer.client.readData(3).payload);
  EXPECT_EQ(first["message"], "[arbiter] info: first line");
  EXPECT_EQ(second["name"], "vision");
  EXPECT_EQ(bridge.stop(), 0) << bridge.output();
  std::filesystem::remove_all(dir);
}

// Newer Foxglove clients offer foxglove.sdk.v1 (the same messages): taken,
// and foxglove.websocket.v1 preferred when both are offered.
TEST_F(LogBridge, AcceptsBothFoxgloveSubprotocols) {
  WsClient sdk("127.0.0.1", bridge_->port(), "/", "", 0, "foxglove.sdk.v1");
  EXPECT_EQ(sdk.subprotocol(), "foxglove.sdk.v1");
  EXPECT_EQ(sdk.readOp("serverInfo")["name"], "beft-bridge");
  WsClient both("127.0.0.1", bridge_->port(), "/", "", 0, "foxglove.sdk.v1, foxglove.websocket.v1");
  EXPECT_EQ(both.subprotocol(), "foxglove.websocket.v1");
}

// Without --net there is no drawing: the page lists the marking instead.
TEST_F(LogBridge, HasNoNetDrawingWithoutANet) {
  Viewer viewer(bridge_->port());
  EXPECT_FALSE(viewer.info["metadata"].contains("net"));
  EXPECT_EQ(httpGet(bridge_->port(), "/net.svg").status, 404);
}

TEST_F(LogBridge, PlaybackControlsFromThisHostWork) {
  Viewer viewer(bridge_->port());
  const uint64_t start_ns = std::stoull(viewer.info["metadata"]["start_ns"].get<std::string>());
  viewer.client.advertise(1, "/beft/playback");
  viewer.client.publish(1, {{"action", "seek"}, {"time_ns", start_ns + 300000000}});
  while (true) {  // the Time frame of the seek
    const Frame frame = viewer.client.read();
    if (frame.text || frame.bytes.size() != 9 || frame.bytes[0] != 2) continue;
    uint64_t t = 0;
    for (int i = 0; i < 8; ++i) t |= uint64_t(static_cast<uint8_t>(frame.bytes[1 + i])) << (8 * i);
    if (t == start_ns + 300000000) break;
  }
  viewer.client.publish(1, {{"action", "seek"}});
  EXPECT_NE(viewer.client.readOp("status")["message"].get<std::string>().find("time_ns"), std::string::npos);
}

TEST(BridgeTokens, ControlsFromAnotherHostNeedTheToken) {
  const std::string address = nonLoopbackAddress();
  if (address.empty()) GTEST_SKIP() << "this host has no IPv4 address but loopback: no other host to be";
  BridgeProgram bridge({"--log", kLog, "--paused", "--bind", "0.0.0.0", "--token", "s3cret", "--lcm-url", "memq://"});
  ASSERT_TRUE(bridge.listening()) << bridge.output();
  Viewer stranger(bridge.port(), "/", address, address);
  stranger.client.advertise(1, "/beft/playback");
  stranger.client.publish(1, {{"action", "play"}});
  const json refused = stranger.client.readOp("status");
  EXPECT_EQ(refused["level"], 2);
  EXPECT_NE(refused["message"].get<std::string>().find("token"), std::string::npos);
  Viewer trusted(bridge.port(), "/?token=s3cret", address, address);
  trusted.client.advertise(1, "/beft/playback");
  trusted.client.publish(1, {{"action", "seek"}});  // let in: answered as a request, not refused
  const json answered = trusted.client.readOp("status");
  EXPECT_NE(answered["message"].get<std::string>().find("time_ns"), std::string::npos);
  EXPECT_EQ(answered["message"].get<std::string>().find("token"), std::string::npos);
}

// beft-bridge on a live run's LCM port (the test's own, the test playing the
// run): a viewer's controls reach the run as RUN_CONTROL (sent again until
// the arbiter's answer) and TASK_COMMAND, and a viewer that never reads
// while the run streams camera frames costs the bridge bounded memory.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <thread>

#include <lcm/lcm-cpp.hpp>

#include <beft/camera_frame_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/run_control_t.hpp>
#include <beft/task_command_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/launch/free_port.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/transport/transport.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/run_identity.hpp"
#include "tests/services/bridge/bridge_client.hpp"

using namespace beft;
using namespace beft::bridge_test;
using nlohmann::json;

namespace {

uint32_t channelId(const json& advertise, const std::string& topic) {
  for (const auto& channel : advertise["channels"])
    if (channel["topic"] == topic) return channel["id"].get<uint32_t>();
  ADD_FAILURE() << topic << " not advertised";
  return 0;
}

class LiveBridge : public ::testing::Test {
 protected:
  void SetUp() override {
    url_ = lcmUrlForPort(launch::findFreeUdpPort());
    run_ = 0x5eed0000 + getpid();
    wire::setRunId(run_);
    lcm_ = std::make_unique<lcm::LCM>(url_);
    ASSERT_TRUE(lcm_->good());
    publishing_ = transport::attachPublisher(*lcm_, url_, "bridge_test");  // serves repairs, as a run's processes do
    bridge_ = std::make_unique<BridgeProgram>(std::vector<std::string>{"--lcm-url", url_},
                                              std::map<std::string, std::string>{{"BEFT_RUN_ID", wire::runIdText(run_)}});
    ASSERT_TRUE(bridge_->listening()) << bridge_->output();
  }
  void TearDown() override {
    if (bridge_) {
      EXPECT_EQ(bridge_->stop(), 0) << bridge_->output();
    }
    publishing_.reset();  // before the LCM it serves
  }
  // Receives `channels` until `done` says so (the run's side of the bridge).
  void receive(const std::vector<std::string>& channels, const std::function<bool(const transport::Message&)>& done) {
    transport::Selection selection;
    for (const auto& c : channels) selection.rules.push_back(transport::channelRule(c));
    auto receiver = transport::openReceiver(*lcm_, url_, selection);
    bool finished = false;
    while (!finished) receiver->receive(100, [&](const transport::Message& m) { finished = finished || done(m); });
  }
  std::string url_;
  int64_t run_ = 0;
  std::unique_ptr<lcm::LCM> lcm_;
  std::unique_ptr<transport::PublisherScope> publishing_;
  std::unique_ptr<BridgeProgram> bridge_;
};

beft::camera_frame_t colourFrame(int64_t tick) {
  beft::camera_frame_t frame{};
  frame.utime = tick * 100000;
  frame.tick = tick;
  frame.encoding = beft::camera_frame_t::ENCODING_RGB8;
  frame.compression = beft::camera_frame_t::COMPRESSION_NONE;
  frame.width = 640;
  frame.height = 480;
  frame.fov = 60;
  frame.range = 10;
  frame.data_size = frame.width * frame.height * 3;
  frame.data.assign(static_cast<std::size_t>(frame.data_size), static_cast<uint8_t>(tick));
  return frame;
}

}  // namespace

TEST_F(LiveBridge, ControlsFromThisHostReachTheRun) {
  WsClient viewer("127.0.0.1", bridge_->port());
  EXPECT_EQ(viewer.readOp("serverInfo")["metadata"]["run"], wire::runIdText(run_));
  viewer.readOp("advertise");
  viewer.advertise(1, "/beft/task");
  viewer.advertise(2, "/beft/run_control");
  viewer.publish(1, {{"action", "goto"}, {"x", 12}, {"y", 8}, {"yaw", 90}});
  viewer.publish(2, {{"action", "pause"}});
  int run_controls = 0;
  bool got_task = false;
  beft::run_control_t request{};
  receive({channels::kTaskCommand.name, channels::kRunControl.name}, [&](const transport::Message& m) {
    if (m.channel == channels::kTaskCommand) {
      beft::task_command_t command{};
      EXPECT_TRUE(wire::decodeFrom(std::string(m.channel), m.data, m.size, command));
      EXPECT_EQ(command.task.kind, "goto");
      EXPECT_EQ(command.task.origin, "viewer");
      EXPECT_DOUBLE_EQ(command.task.x, 12);
      got_task = true;
    } else if (wire::decodeFrom(std::string(m.channel), m.data, m.size, request)) {
      EXPECT_EQ(request.mode, beft::run_control_t::MODE_PAUSE);
      ++run_controls;
    }
    return got_task && run_controls >= 2;  // sent again while the arbiter has not answered
  });
  // The arbiter's answer: the viewer is told.
  beft::run_control_t state = request;
  state.tick = 5;
  transport::publish(*lcm_, wire::runChannel(channels::kRunControlState), state);
  const json told = viewer.readOp("status");
  EXPECT_EQ(told["level"], 0);
  EXPECT_NE(told["message"].get<std::string>().find("paused"), std::string::npos) << told.dump();
}

TEST_F(LiveBridge, AViewerThatNeverReadsCostsBoundedMemory) {
  WsClient idle("127.0.0.1", bridge_->port(), "/", "", 64 * 1024);
  idle.readOp("serverInfo");
  const json advertise = idle.readOp("advertise");
  json subscriptions = json::array();
  uint32_t id = 1;
  for (const char* topic : {"CAMERA_COLOR", "/camera/color", "ROBOT_STATE", "/scene", "/tf"})
    subscriptions.push_back({{"id", id++}, {"channelId", channelId(advertise, topic)}});
  idle.sendJson(json{{"op", "subscribe"}, {"subscriptions", subscriptions}});
  // The run streams: 300 ticks of a 640 x 480 colour frame and a robot state, about 280 MB.
  long peak_kb = 0;
  for (int64_t tick = 0; tick < 300; ++tick) {
    transport::publish(*lcm_, wire::runChannel(channels::kCameraColor), colourFrame(tick));
    beft::robot_state_t robot{};
    robot.tick = tick;
    robot.utime = tick * 100000;
    transport::publish(*lcm_, wire::runChannel(channels::kRobotState), robot);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (tick % 20 == 0) peak_kb = std::max(peak_kb, bridge_->residentKilobytes());
  }
  peak_kb = std::max(peak_kb, bridge_->residentKilobytes());
  std::printf("bridge resident memory, a viewer never reading 300 frames of 0.9 MB: %.1f MB at most\n", peak_kb / 1024.0);
  EXPECT_GT(peak_kb, 0);
  EXPECT_LT(peak_kb, 200 * 1024);
  // Another viewer is served meanwhile, and the idle one, reading at last, is told what it lost.
  WsClient other("127.0.0.1", bridge_->port());
  other.readOp("serverInfo");
  other.sendJson(json{{"op", "subscribe"}, {"subscriptions", {{{"id", 1}, {"channelId", channelId(advertise, "ROBOT_STATE")}}}}});
  beft::robot_state_t robot{};
  robot.tick = 1000;
  transport::publish(*lcm_, wire::runChannel(channels::kRobotState), robot);
  EXPECT_TRUE(json::parse(other.readData(1).payload).contains("tick"));
  bool told = false;
  while (!told) {
    const json status = idle.readOp("status");
    told = status["message"].get<std::string>().find("not sent") != std::string::npos;
  }
  EXPECT_TRUE(told);
}

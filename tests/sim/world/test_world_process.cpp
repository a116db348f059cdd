// beft-world as a real process on its own LCM port: driven by FIRE tokens
// from the test (lockstep) and free-running (--realtime). The test counts the
// messages of each type per tick and checks them against the scenario and
// against the same world simulated in-process.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <beft/camera_frame_t.hpp>
#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/heartbeat_t.hpp>
#include <beft/robot_command_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/run_status_t.hpp>
#include <beft/scene_version_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/camera/camera_messages.hpp"
#include "lib/common/channels.hpp"
#include "lib/camera/frame_compressor.hpp"
#include "lib/camera/frame_decoding.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/wire/envelope.hpp"
#include "sim/world/world_simulation.hpp"

extern char** environ;

namespace {

using Clock = std::chrono::steady_clock;

const std::string kYard = std::string(BEFT_SCENARIO_DIR) + "/yard.xml";
// What the world publishes at every tick; GT_OBJECTS only when the scene
// changes and at keyframes (GT_VERSION says which one holds).
const std::vector<std::string> kWorldChannels = {beft::channels::kSceneVersion, beft::channels::kRobotState,
                                                 beft::channels::kCameraColor, beft::channels::kCameraDepth,
                                                 beft::channels::kCameraInstance};

// A port of its own per test and process.
int testPort(int offset) { return 20000 + (getpid() * 7 + offset) % 20000; }

// beft-world as a child process, its output in a file (shown on failure).
class WorldProcess {
 public:
  explicit WorldProcess(std::vector<std::string> args) {
    output_file_ = "/tmp/beft_test_world_" + std::to_string(getpid()) + "_" + std::to_string(++counter_) + ".log";
    args.insert(args.begin(), BEFT_WORLD_BINARY);
    posix_spawn_file_actions_t actions{};
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, output_file_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
  }
  ~WorldProcess() {
    if (running()) {
      kill(pid_, SIGTERM);
      waitExit(5.0);
    }
    std::remove(output_file_.c_str());
  }
  bool started() const { return pid_ > 0; }
  bool running() {
    if (pid_ <= 0 || exited_) return false;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      exited_ = true;
      code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    return !exited_;
  }
  // The exit code, or -1 if it was still running after `seconds` (then killed).
  int waitExit(double seconds) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (running()) {
      if (Clock::now() > deadline) {
        kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
        exited_ = true;
        return -1;
      }
      usleep(10000);
    }
    return code_;
  }
  std::string output() const {
    std::ifstream in(output_file_);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

 private:
  static inline int counter_ = 0;
  pid_t pid_ = -1;
  bool exited_ = false;
  int code_ = -1;
  std::string output_file_;
};

// Everything heard on the world's channels, DONE and HEARTBEAT, as the world
// encoded it (the transport's envelope left out).
class Listener {
 public:
  explicit Listener(lcm::LCM& lcm) {
    for (const std::string& channel : kWorldChannels) {
      lcm.subscribe(channel, &Listener::onMessage, this)->setQueueCapacity(10000);
    }
    lcm.subscribe(beft::channels::kGroundTruth, &Listener::onMessage, this)->setQueueCapacity(10000);
    lcm.subscribe(beft::channels::kDone, &Listener::onMessage, this)->setQueueCapacity(10000);
    lcm.subscribe(beft::channels::kHeartbeat, &Listener::onMessage, this)->setQueueCapacity(10000);
  }
  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    const auto* bytes = static_cast<const uint8_t*>(buffer->data);
    messages[channel].emplace_back(bytes, bytes + beft::wire::payloadSize(bytes, buffer->data_size));
  }
  template <typename Message>
  std::vector<Message> decoded(const std::string& channel) const {
    std::vector<Message> out;
    const auto found = messages.find(channel);
    if (found == messages.end()) return out;
    for (const auto& bytes : found->second) {
      Message message;
      if (message.decode(bytes.data(), 0, static_cast<int>(bytes.size())) == static_cast<int>(bytes.size()))
        out.push_back(message);
    }
    return out;
  }
  // Camera frames as a reader gets them: decoded, then unpacked.
  std::vector<beft::camera_frame_t> frames(const std::string& channel) const {
    std::vector<beft::camera_frame_t> out;
    for (auto frame : decoded<beft::camera_frame_t>(channel)) {
      std::string why;
      EXPECT_NE(frame.compression, beft::camera_frame_t::COMPRESSION_NONE) << channel;
      EXPECT_TRUE(beft::camera::decodeCameraFrame(frame, &why)) << channel << ": " << why;
      out.push_back(std::move(frame));
    }
    return out;
  }
  size_t count(const std::string& channel) const {
    const auto found = messages.find(channel);
    return found == messages.end() ? 0 : found->second.size();
  }
  std::map<std::string, std::vector<std::vector<uint8_t>>> messages;
};

// Handles LCM until `done` holds or the budget runs out.
template <typename Predicate>
bool handleUntil(lcm::LCM& lcm, double seconds, Predicate done) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  while (!done()) {
    if (Clock::now() > deadline) return false;
    lcm.handleTimeout(20);
  }
  return true;
}

template <typename Message>
std::vector<uint8_t> encoded(const Message& message) {
  std::vector<uint8_t> bytes(message.getEncodedSize());
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

beft::robot_command_t velocityCommand(double vx, double vy, double yaw_rate) {
  beft::robot_command_t command{};
  command.mode = beft::robot_command_t::MODE_VELOCITY;
  command.vx = vx;
  command.vy = vy;
  command.yaw_rate = yaw_rate;
  command.source = "test";
  return command;
}

// The ground truth must be the scenario's objects (at t = 0: where the file puts them).
void expectScenarioObjects(const beft::scene_objects_t& truth, const beft::scenario::Scenario& scenario) {
  ASSERT_EQ(truth.num_objects, static_cast<int>(scenario.objects.size()));
  for (size_t i = 0; i < scenario.objects.size(); ++i) {
    EXPECT_EQ(truth.objects[i].id, scenario.objects[i].id);
    EXPECT_EQ(truth.objects[i].label, scenario.objects[i].label);
    EXPECT_DOUBLE_EQ(truth.objects[i].x, scenario.objects[i].x);
    EXPECT_DOUBLE_EQ(truth.objects[i].y, scenario.objects[i].y);
  }
  EXPECT_EQ(truth.scenario, scenario.name);
}

}  // namespace

TEST(WorldProcess, LockstepPublishesEachTickAsTheInProcessWorldDoes) {
  const std::string url = beft::lcmUrlForPort(testPort(1));
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good());
  Listener listener(lcm);
  WorldProcess world({"--scenario", kYard, "--lcm-url", url, "--no-catch-up", "--heartbeat-period", "0.1"});
  ASSERT_TRUE(world.started());
  ASSERT_TRUE(handleUntil(lcm, 15.0, [&] { return listener.count(beft::channels::kHeartbeat) > 0; }))
      << world.output();

  // The same world in-process, fed the same commands at the same ticks.
  const beft::scenario::Scenario scenario = beft::scenario::loadScenario(kYard, nullptr);
  beft::world::WorldOptions options;
  options.seed = scenario.seed;
  beft::world::WorldSimulation reference(scenario, options);
  beft::camera::FrameCompressor compressor;
  std::map<std::string, std::vector<std::vector<uint8_t>>> expected;

  constexpr int kTicks = 12;
  for (int k = 0; k < kTicks; ++k) {
    beft::robot_command_t command{};
    bool send_command = false;
    if (k == 3) {
      command = velocityCommand(0.8, 0.3, 20);
      command.set_head = true;
      command.head_yaw = 30;
      command.head_pitch = -5;
      send_command = true;
    } else if (k == 7) {
      command = velocityCommand(NAN, 0, 0);  // refused: the one in force stays
      send_command = true;
    }
    if (send_command) {
      lcm.publish(beft::channels::kRobotCommand, &command);
      reference.submitCommand(command);
    }
    if (k > 0) reference.step();
    beft::camera::CameraMessages rendered, camera;
    reference.cameraMessages(rendered);
    compressor.compress(rendered, camera);  // as the world publishes them
    if (reference.sceneTick() == k) expected[beft::channels::kGroundTruth].push_back(encoded(reference.groundTruth()));
    expected[beft::channels::kSceneVersion].push_back(encoded(reference.sceneVersion()));
    expected[beft::channels::kRobotState].push_back(encoded(reference.robotState()));
    expected[beft::channels::kCameraColor].push_back(encoded(camera.color));
    expected[beft::channels::kCameraDepth].push_back(encoded(camera.depth));
    expected[beft::channels::kCameraInstance].push_back(encoded(camera.instance));

    beft::fire_t fire{};
    fire.utime = static_cast<int64_t>(k) * 100000;
    fire.expert = "world";
    fire.transition = "world";
    fire.tick = k;
    fire.firing_id = 1000 + k;
    const auto doneFor = [&] {
      for (const auto& done : listener.decoded<beft::done_t>(beft::channels::kDone))
        if (done.firing_id == fire.firing_id) return true;
      return false;
    };
    // Re-sent until DONE, as the arbiter does.
    bool done = false;
    for (int attempt = 0; attempt < 20 && !done; ++attempt) {
      lcm.publish(beft::channels::kFire, &fire);
      done = handleUntil(lcm, 0.5, doneFor);
    }
    ASSERT_TRUE(done) << "no DONE for tick " << k << "\n" << world.output();
  }
  handleUntil(lcm, 0.3, [] { return false; });  // anything still in flight

  for (const auto& done : listener.decoded<beft::done_t>(beft::channels::kDone)) {
    EXPECT_EQ(done.outcome, beft::done_t::OUTCOME_OK) << done.message;
  }
  // Nothing in yard moves and no event is due by then: one ground truth, at tick 0.
  ASSERT_EQ(expected[beft::channels::kGroundTruth].size(), 1u);
  std::vector<std::string> published = kWorldChannels;
  published.push_back(beft::channels::kGroundTruth);
  for (const std::string& channel : published) {
    ASSERT_EQ(listener.count(channel), expected[channel].size()) << channel;
    for (std::size_t i = 0; i < expected[channel].size(); ++i) {
      EXPECT_EQ(listener.messages[channel][i], expected[channel][i]) << channel << " message " << i;
    }
  }
  for (const auto& version : listener.decoded<beft::scene_version_t>(beft::channels::kSceneVersion))
    EXPECT_EQ(version.scene_tick, 0);
  // And what those messages say, against the scenario.
  const auto truths = listener.decoded<beft::scene_objects_t>(beft::channels::kGroundTruth);
  ASSERT_EQ(truths.size(), 1u);
  expectScenarioObjects(truths[0], scenario);
  const auto states = listener.decoded<beft::robot_state_t>(beft::channels::kRobotState);
  EXPECT_EQ(states[0].x, scenario.robot.x);
  EXPECT_EQ(states[2].x, scenario.robot.x);  // no command before tick 3
  EXPECT_NEAR(states[3].x, scenario.robot.x + 0.08, 1e-9);
  EXPECT_NEAR(states[kTicks - 1].x, scenario.robot.x + 0.08 * (kTicks - 3), 1e-9);
  EXPECT_NEAR(states[kTicks - 1].head_yaw, 30, 1e-9);
  for (int k = 0; k < kTicks; ++k) EXPECT_EQ(states[k].tick, k);
  const auto instances = listener.frames(beft::channels::kCameraInstance);
  ASSERT_EQ(instances.size(), static_cast<size_t>(kTicks));
  std::string why;
  ASSERT_TRUE(beft::camera::validCameraFrame(instances[0], &why)) << why;
  EXPECT_EQ(instances[0].instance_ids[0], "victim_seen");
  // victim_seen stands in plain view of the start pose.
  int victim_pixels = 0;
  for (int v = 0; v < instances[0].height; ++v)
    for (int u = 0; u < instances[0].width; ++u) victim_pixels += beft::camera::instanceAt(instances[0], u, v) == 0;
  EXPECT_GT(victim_pixels, 50);
  EXPECT_NE(world.output().find("non-finite"), std::string::npos);  // the refused command was logged

  beft::run_status_t status{};
  status.utime = 0;
  status.tick = kTicks;
  status.state = beft::run_status_t::STATE_FINISHED;
  status.message = "test over";
  lcm.publish(beft::channels::kRunStatus, &status);
  EXPECT_EQ(world.waitExit(10.0), 0) << world.output();
}

TEST(WorldProcess, FreeRunningPublishesEveryTickAndTakesCommands) {
  // A small camera keeps each tick's messages far below the socket buffer,
  // so a test process that is not scheduled for a while loses nothing.
  const std::string scenario_path = "/tmp/beft_test_world_free_" + std::to_string(getpid()) + ".xml";
  {
    std::ofstream out(scenario_path);
    out << R"(<?xml version="1.0" encoding="UTF-8"?>
<scenario name="free_running" dt="0.1" duration="60" seed="3">
  <world width="30" height="20"/>
  <robot x="2" y="2"><camera width="40" height="30"/></robot>
  <object id="victim" label="person" x="9" y="2">
    <visual shape="cylinder" radius="0.3" height="1.8" color="#3060d0"/>
  </object>
  <object id="wall1" label="wall" x="12" y="6" yaw="90">
    <visual shape="box" size="6 0.2 2.5"/>
  </object>
</scenario>
)";
  }
  const std::string url = beft::lcmUrlForPort(testPort(2));
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good());
  Listener listener(lcm);
  constexpr int kLastTick = 30;
  WorldProcess world(
      {"--scenario", scenario_path, "--lcm-url", url, "--realtime", "40", "--ticks", std::to_string(kLastTick)});
  ASSERT_TRUE(world.started());
  // Once tick 2 is out, command a motion; later ticks must show it.
  ASSERT_TRUE(handleUntil(lcm, 15.0, [&] { return listener.count(beft::channels::kRobotState) >= 3; }))
      << world.output();
  const beft::robot_command_t command = velocityCommand(0.0, 0.5, 0.0);
  lcm.publish(beft::channels::kRobotCommand, &command);
  ASSERT_TRUE(handleUntil(lcm, 15.0, [&] {
    for (const std::string& channel : kWorldChannels)
      if (listener.count(channel) < kLastTick + 1) return false;
    return true;
  })) << world.output();
  EXPECT_EQ(world.waitExit(10.0), 0) << world.output();
  handleUntil(lcm, 0.2, [] { return false; });

  const beft::scenario::Scenario scenario = beft::scenario::loadScenario(scenario_path, nullptr);
  std::remove(scenario_path.c_str());
  for (const std::string& channel : kWorldChannels) EXPECT_EQ(listener.count(channel), kLastTick + 1u) << channel;
  const auto truths = listener.decoded<beft::scene_objects_t>(beft::channels::kGroundTruth);
  const auto versions = listener.decoded<beft::scene_version_t>(beft::channels::kSceneVersion);
  const auto states = listener.decoded<beft::robot_state_t>(beft::channels::kRobotState);
  ASSERT_EQ(states.size(), kLastTick + 1u);
  ASSERT_EQ(versions.size(), kLastTick + 1u);
  for (int k = 0; k <= kLastTick; ++k) {
    EXPECT_EQ(versions[k].tick, k);
    EXPECT_EQ(versions[k].scene_tick, 0);  // nothing in this scene moves or changes
    EXPECT_EQ(states[k].tick, k);
    EXPECT_EQ(states[k].utime, k * 100000);
  }
  ASSERT_EQ(truths.size(), 1u);
  EXPECT_EQ(truths[0].tick, 0);
  expectScenarioObjects(truths[0], scenario);
  EXPECT_EQ(states[0].x, 2.0);
  EXPECT_EQ(states[0].y, 2.0);
  // Driven north at 0.5 m/s for at least the last few ticks.
  EXPECT_GT(states[kLastTick].y, 2.2);
  EXPECT_EQ(states[kLastTick].x, 2.0);
  EXPECT_NEAR(states[kLastTick].vy, 0.5, 1e-9);
  EXPECT_NE(states[kLastTick].last_command.find("velocity"), std::string::npos);
  ASSERT_FALSE(listener.frames(beft::channels::kCameraDepth).empty());
  for (const auto& frame : listener.frames(beft::channels::kCameraDepth)) {
    std::string why;
    EXPECT_TRUE(beft::camera::validCameraFrame(frame, &why)) << why;
    EXPECT_EQ(frame.width, 40);
    EXPECT_EQ(frame.height, 30);
  }
  // The victim stands on the optical axis, its near side 6.7 m ahead. Pixel
  // (20, 15)'s ray runs half a pixel (0.025 t) to the right, meeting the
  // cylinder (centre 7 m ahead, radius 0.3) at t = 7 - sqrt(0.09 - (0.025 t)^2)
  // = 6.75 m.
  const auto depth = listener.frames(beft::channels::kCameraDepth).at(0);
  const auto instance = listener.frames(beft::channels::kCameraInstance).at(0);
  EXPECT_EQ(beft::camera::instanceAt(instance, 20, 15), 0);
  EXPECT_NEAR(beft::camera::depthAt(depth, 20, 15), 6.752, 0.002);
}

TEST(WorldProcess, RefusesABadScenarioWithFileAndLine) {
  const std::string path = "/tmp/beft_test_world_bad_" + std::to_string(getpid()) + ".xml";
  {
    std::ofstream out(path);
    out << "<?xml version=\"1.0\"?>\n<scenario name=\"bad\">\n  <world width=\"-3\" height=\"10\"/>\n"
           "  <robot x=\"1\" y=\"1\"/>\n</scenario>\n";
  }
  WorldProcess world({"--scenario", path});
  ASSERT_TRUE(world.started());
  EXPECT_EQ(world.waitExit(10.0), 2);
  EXPECT_NE(world.output().find(path + ":3:"), std::string::npos) << world.output();
  std::remove(path.c_str());
}

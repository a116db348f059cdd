// The six expert processes over real LCM: the test plays the world and the
// arbiter on its own UDP port (ground truth, robot state and camera frames of
// one tick, then FIRE tokens level by level) and checks every DONE and every
// published output against the logic libraries and the model library.
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/geometry_percepts_t.hpp>
#include <beft/heartbeat_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/labels_t.hpp>
#include <beft/obstacle_map_t.hpp>
#include <beft/visual_percepts_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/camera/camera_messages.hpp"
#include "lib/common/channels.hpp"
#include "experts/geometry/geometry_estimator.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/model/model.hpp"
#include "lib/wire/obstacle_map_codec.hpp"
#include "lib/scene/ray_caster.hpp"
#include "tests/experts/support/scene_builders.hpp"
#include "lib/scene/scene_geometry.hpp"

extern char** environ;

using namespace beft;

namespace {

using Clock = std::chrono::steady_clock;

struct ExpertBinary {
  std::string name;
  std::string path;
};

const std::vector<ExpertBinary> kExperts = {
    {"geometry", BEFT_GEOMETRY_BIN},           {"vision", BEFT_VISION_BIN},
    {"audio", BEFT_AUDIO_BIN},                 {"visual_labels", BEFT_VISUAL_LABELS_BIN},
    {"acoustic_labels", BEFT_ACOUSTIC_LABELS_BIN}, {"fusion", BEFT_FUSION_BIN}};

// Everything the experts publish, as the test received it.
class Listener {
 public:
  explicit Listener(lcm::LCM& lcm) : lcm_(lcm) {
    subscribe<done_t>(channels::kDone, [this](const done_t& m) { done[m.firing_id] = m; });
    subscribe<heartbeat_t>(channels::kHeartbeat, [this](const heartbeat_t& m) { alive.insert(m.process); });
    subscribe<geometry_percepts_t>(channels::kGeometry, [this](const geometry_percepts_t& m) { geometry = m; });
    subscribe<visual_percepts_t>(channels::kVision, [this](const visual_percepts_t& m) { vision = m; });
    subscribe<obstacle_map_t>(channels::kObstacleMap, [this](const obstacle_map_t& m) { map = m; });
    subscribe<acoustic_percepts_t>(channels::kAudio, [this](const acoustic_percepts_t& m) { audio = m; });
    subscribe<labels_t>(channels::kLabelsVisual, [this](const labels_t& m) { visual_labels = m; });
    subscribe<labels_t>(channels::kLabelsAcoustic, [this](const labels_t& m) { acoustic_labels = m; });
    subscribe<hypotheses_t>(channels::kHypotheses, [this](const hypotheses_t& m) { hypotheses = m; });
  }

  // Handles messages until done() holds or the wall-clock budget is spent.
  bool waitFor(const std::function<bool()>& done_when, double seconds) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (!done_when()) {
      if (Clock::now() > deadline) return false;
      lcm_.handleTimeout(20);
    }
    return true;
  }

  std::map<int64_t, done_t> done;
  std::set<std::string> alive;
  std::optional<geometry_percepts_t> geometry;
  std::optional<visual_percepts_t> vision;
  std::optional<obstacle_map_t> map;
  std::optional<acoustic_percepts_t> audio;
  std::optional<labels_t> visual_labels, acoustic_labels;
  std::optional<hypotheses_t> hypotheses;

 private:
  template <typename Message>
  void subscribe(const std::string& channel, std::function<void(const Message&)> store) {
    handlers_.push_back(std::make_unique<Handler<Message>>(std::move(store)));
    auto* handler = static_cast<Handler<Message>*>(handlers_.back().get());
    lcm_.subscribe(channel, &Handler<Message>::handle, handler)->setQueueCapacity(1000);
  }
  struct HandlerBase {
    virtual ~HandlerBase() = default;
  };
  template <typename Message>
  struct Handler : HandlerBase {
    explicit Handler(std::function<void(const Message&)> s) : store(std::move(s)) {}
    void handle(const lcm::ReceiveBuffer*, const std::string&, const Message* m) { store(*m); }
    std::function<void(const Message&)> store;
  };
  lcm::LCM& lcm_;
  std::vector<std::unique_ptr<HandlerBase>> handlers_;
};

class ExpertProcesses : public ::testing::Test {
 protected:
  void SetUp() override {
    url_ = lcmUrlForPort(20000 + static_cast<int>(getpid() % 20000));
    lcm_ = std::make_unique<lcm::LCM>(url_);
    ASSERT_TRUE(lcm_->good()) << url_;
    listener_ = std::make_unique<Listener>(*lcm_);
    for (const auto& expert : kExperts) start(expert);
  }

  void TearDown() override {
    for (pid_t pid : children_) kill(pid, SIGTERM);
    for (pid_t pid : children_) {
      int status = 0;
      waitpid(pid, &status, 0);
    }
  }

  void start(const ExpertBinary& expert) {
    std::vector<std::string> args = {expert.path, "--lcm-url", url_, "--no-catch-up",
                                     "--heartbeat-period", "0.1", "--ready-timeout", "0.3"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, expert.path.c_str(), nullptr, nullptr, argv.data(), environ), 0) << expert.path;
    children_.push_back(pid);
  }

  template <typename Message>
  void publish(const std::string& channel, const Message& message) {
    ASSERT_EQ(lcm_->publish(channel, &message), 0) << channel;
  }

  // Sends FIRE tokens and waits for their DONE, re-sending every second.
  bool fire(const std::vector<std::pair<std::string, int64_t>>& tokens, int64_t tick) {
    const auto send = [&] {
      for (const auto& [expert, firing_id] : tokens) {
        fire_t f{};
        f.utime = tick * 100000;
        f.expert = expert;
        f.transition = "t_" + expert;
        f.tick = tick;
        f.firing_id = firing_id;
        lcm_->publish(channels::kFire, &f);
      }
    };
    const auto all_done = [&] {
      for (const auto& token : tokens)
        if (!listener_->done.count(token.second)) return false;
      return true;
    };
    for (int attempt = 0; attempt < 10; ++attempt) {
      send();
      if (listener_->waitFor(all_done, 1.0)) return true;
    }
    return false;
  }

  std::string url_;
  std::unique_ptr<lcm::LCM> lcm_;
  std::unique_ptr<Listener> listener_;
  std::vector<pid_t> children_;
};

template <typename Percepts>
const auto* perceptOf(const Percepts& percepts, const std::string& id) {
  for (const auto& p : percepts.percepts)
    if (p.object_id == id) return &p;
  return static_cast<decltype(&percepts.percepts[0])>(nullptr);
}

}  // namespace

TEST_F(ExpertProcesses, OneTickThroughAllLevelsMatchesTheModel) {
  ASSERT_TRUE(listener_->waitFor([&] { return listener_->alive.size() == kExperts.size(); }, 15.0))
      << "only " << listener_->alive.size() << " experts sent a heartbeat";

  // The scene: a yelling victim in view, a radio behind a wall that sounds
  // like a person, a car to the left.
  const auto scene = test::scene(
      {test::sounding(test::cylinderObject("victim", "person", 8, 5, 0.3, 1.8), "yelling"),
       test::boxObject("wall", "wall", 6, 9, 90, 3, 0.2, 2.5),
       test::sounding(test::boxObject("radio", "siren", 9, 10, 0, 0.4, 0.3, 0.3), "playing", "person"),
       test::boxObject("car", "car", 4, 8, 0, 3, 1.6, 1.5)},
      0);
  const auto robot = test::robot(2, 5, 10, 5);
  const auto solids = camera::SceneGeometry::fromMessage(scene);
  camera::CameraIntrinsics intrinsics;
  const auto cam = camera::cameraOnRobot(robot, intrinsics);
  camera::CameraMessages frames;
  std::vector<std::string> ids;
  for (const auto& o : scene.objects) ids.push_back(o.id);
  camera::encodeCameraMessages(camera::renderFrame(solids, cam), scene.utime, scene.tick, ids, frames);

  publish(channels::kGroundTruth, scene);
  publish(channels::kRobotState, robot);
  publish(channels::kCameraDepth, frames.depth);
  publish(channels::kCameraInstance, frames.instance);

  // Low level together, then mid level together, then fusion.
  ASSERT_TRUE(fire({{"geometry", 1}, {"vision", 2}, {"audio", 3}}, 0));
  ASSERT_TRUE(fire({{"visual_labels", 4}, {"acoustic_labels", 5}}, 0));
  ASSERT_TRUE(fire({{"fusion", 6}}, 0));
  for (int64_t id = 1; id <= 6; ++id) {
    const done_t& d = listener_->done.at(id);
    EXPECT_EQ(d.outcome, done_t::OUTCOME_OK) << d.expert << ": " << d.message;
    EXPECT_EQ(d.tick, 0);
  }
  ASSERT_TRUE(listener_->waitFor([&] { return listener_->hypotheses.has_value(); }, 2.0));

  // GEOMETRY: the geometry logic on the same inputs, field by field.
  ASSERT_TRUE(listener_->geometry);
  const auto expected_geometry = geometry::estimateGeometry(scene, robot);
  ASSERT_EQ(listener_->geometry->num_percepts, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(listener_->geometry->percepts[i].object_id, expected_geometry.percepts[i].object_id);
    EXPECT_DOUBLE_EQ(listener_->geometry->percepts[i].distance, expected_geometry.percepts[i].distance);
    EXPECT_DOUBLE_EQ(listener_->geometry->percepts[i].azimuth, expected_geometry.percepts[i].azimuth);
  }

  // VISION: the victim in plain view, the radio hidden behind the wall.
  ASSERT_TRUE(listener_->vision);
  const auto* victim_seen = perceptOf(*listener_->vision, "victim");
  ASSERT_NE(victim_seen, nullptr);
  EXPECT_GT(victim_seen->visible_pixels, 50);
  EXPECT_DOUBLE_EQ(victim_seen->occlusion, 0.0);
  const auto* radio_seen = perceptOf(*listener_->vision, "radio");
  ASSERT_NE(radio_seen, nullptr);
  EXPECT_EQ(radio_seen->visible_pixels, 0);
  EXPECT_DOUBLE_EQ(radio_seen->occlusion, 100.0);

  // OBSTACLE_MAP: a 30 x 20 m world at 0.1 m with obstacles where the camera saw them.
  ASSERT_TRUE(listener_->map);
  const auto cells = planners::decodeObstacleMap(*listener_->map);
  EXPECT_EQ(cells.width, 300);
  EXPECT_EQ(cells.height, 200);
  auto occupiedWithin = [&](double x0, double x1, double y0, double y1) {
    int count = 0;
    for (int row = static_cast<int>(y0 / 0.1); row < static_cast<int>(y1 / 0.1); ++row)
      for (int column = static_cast<int>(x0 / 0.1); column < static_cast<int>(x1 / 0.1); ++column)
        count += cells.at(column, row) == obstacle_map_t::CELL_OCCUPIED;
    return count;
  };
  EXPECT_GT(occupiedWithin(7.6, 8.4, 4.6, 5.4), 0);    // the victim's near side
  EXPECT_EQ(occupiedWithin(3.0, 7.0, 4.5, 5.5), 0);    // the floor between robot and victim
  EXPECT_EQ(cells.at(50, 50), obstacle_map_t::CELL_FREE);

  // AUDIO: two sounding objects; the radio's lines all pass through the wall.
  ASSERT_TRUE(listener_->audio);
  ASSERT_EQ(listener_->audio->num_percepts, 2);
  EXPECT_DOUBLE_EQ(perceptOf(*listener_->audio, "victim")->occlusion, 0.0);
  EXPECT_DOUBLE_EQ(perceptOf(*listener_->audio, "radio")->occlusion, 100.0);
  EXPECT_EQ(perceptOf(*listener_->audio, "radio")->acoustic_label, "person");

  // LABELS_*: eqs. 1-3 of the model library on the published geometry and occlusions.
  ASSERT_TRUE(listener_->visual_labels);
  // One entry per object the camera shows: the radio behind the wall has none.
  int shown = 0;
  for (const auto& percept : listener_->vision->percepts) shown += percept.visible_pixels > 0;
  ASSERT_EQ(shown, 3);
  ASSERT_EQ(listener_->visual_labels->num_objects, shown);
  for (const auto& entry : listener_->visual_labels->objects) EXPECT_NE(entry.object_id, "radio");
  for (const auto& entry : listener_->visual_labels->objects) {
    const auto* g = perceptOf(*listener_->geometry, entry.object_id);
    const auto* v = perceptOf(*listener_->vision, entry.object_id);
    ASSERT_TRUE(g && v) << entry.object_id;
    const double v_p = model::visualPerceptibility(g->distance, v->occlusion);
    EXPECT_DOUBLE_EQ(entry.perceptibility, v_p) << entry.object_id;
    std::string label;
    for (const auto& o : scene.objects)
      if (o.id == entry.object_id) label = o.label;
    EXPECT_EQ(entry.confidence, model::labelConfidences(scene.categories, label, v_p)) << entry.object_id;
  }
  ASSERT_TRUE(listener_->acoustic_labels);
  ASSERT_EQ(listener_->acoustic_labels->num_objects, 2);
  for (const auto& entry : listener_->acoustic_labels->objects) {
    const auto* g = perceptOf(*listener_->geometry, entry.object_id);
    const auto* a = perceptOf(*listener_->audio, entry.object_id);
    ASSERT_TRUE(g && a) << entry.object_id;
    const double a_p = model::acousticPerceptibility(g->distance, a->occlusion, g->azimuth);
    EXPECT_DOUBLE_EQ(entry.perceptibility, a_p) << entry.object_id;
    EXPECT_EQ(entry.confidence, model::labelConfidences(scene.categories, "person", a_p)) << entry.object_id;
  }

  // HYPOTHESES: the victim heard and seen as a person: verified; the radio
  // only heard so far.
  ASSERT_TRUE(listener_->hypotheses);
  std::map<std::string, hypothesis_t> by_id;
  for (const auto& h : listener_->hypotheses->hypotheses) by_id[h.object_id] = h;
  ASSERT_TRUE(by_id.count("victim"));
  EXPECT_TRUE(by_id["victim"].verified);
  EXPECT_EQ(by_id["victim"].best_category, "person");
  ASSERT_TRUE(by_id.count("radio"));
  EXPECT_TRUE(by_id["radio"].heard);
  EXPECT_FALSE(by_id["radio"].seen);
  EXPECT_EQ(by_id["radio"].heard_as, "person");
  EXPECT_FALSE(by_id["radio"].verified || by_id["radio"].falsified);
}

TEST_F(ExpertProcesses, AFiringWithoutItsInputsFailsWithAReason) {
  ASSERT_TRUE(listener_->waitFor([&] { return listener_->alive.size() == kExperts.size(); }, 15.0));
  // Ground truth of tick 3 only: the robot state of tick 4 never comes.
  publish(channels::kGroundTruth, test::scene({test::pointObject("radio", "siren", 5, 5)}, 3));
  ASSERT_TRUE(fire({{"geometry", 11}}, 4));
  const done_t& d = listener_->done.at(11);
  EXPECT_EQ(d.outcome, done_t::OUTCOME_FAILED);
  EXPECT_NE(d.message.find("tick 4"), std::string::npos) << d.message;
  EXPECT_FALSE(listener_->geometry.has_value());
}

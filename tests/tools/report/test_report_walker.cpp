// A person found while walking: its position error is that of its estimate
// when the hypothesis last placed it, against where the person was then (the
// GT_OBJECTS of that tick), not against where it walked to by the end of the
// run (issue 33). On a small LCM log written here.
#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <beft/hypotheses_t.hpp>
#include <beft/hypothesis_changes_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/report/report_json.hpp"
#include "lib/report/run_record.hpp"
#include "lib/report/run_scoring.hpp"
#include "lib/wire/hypothesis_changes.hpp"
#include "tests/tools/report/log_events.hpp"

namespace beft::report {
namespace {

namespace fs = std::filesystem;

constexpr double kDt = 0.1;
constexpr int kTicks = 80;        // 8 s
constexpr int kFirstSeen = 20;    // seen from 2 s ...
constexpr int kLastSeen = 30;     // ... tracked until 3 s, then out of sight
constexpr double kSpeed = 1.0;    // the walker's speed along +x [m/s]
constexpr double kOffset = 0.2;   // the estimate's error along +y while tracked [m]

using report_test::write;

double walkerX(int tick) { return 5 + kSpeed * tick * kDt; }

// The world of tick k: the walker at (walkerX(k), 5), a wall that stays.
scene_objects_t sceneOf(int k) {
  scene_objects_t scene{};
  scene.utime = static_cast<int64_t>(std::llround(k * kDt * 1e6));
  scene.tick = k;
  scene.world_width = 20;
  scene.world_height = 10;
  scene.scenario = "walkeryard";
  scene.dt = kDt;
  scene.duration = 60;
  scene.categories = {"person", "wall"};
  scene.num_categories = 2;
  scene_object_t walker{};
  walker.id = "walker";
  walker.label = "person";
  walker.activity = "walking";
  walker.x = walkerX(k);
  walker.y = 5;
  walker.shape = scene_object_t::SHAPE_CYLINDER;
  walker.radius = 0.3;
  scene_object_t wall{};
  wall.id = "wall";
  wall.label = "wall";
  wall.x = 10;
  wall.y = 9;
  wall.shape = scene_object_t::SHAPE_BOX;
  wall.size_x = 4;
  wall.size_y = 0.2;
  scene.objects = {walker, wall};
  scene.num_objects = 2;
  return scene;
}

// Fusion's belief at tick k: none before the walker is seen; tracked (its
// estimate follows it, kOffset off) while seen; left where it was last seen after.
hypotheses_t hypothesesOf(int k) {
  hypotheses_t message{};
  message.utime = static_cast<int64_t>(std::llround(k * kDt * 1e6));
  message.tick = k;
  if (k >= kFirstSeen) {
    hypothesis_t h{};
    h.object_id = "walker";
    h.x = walkerX(std::min(k, kLastSeen));
    h.y = 5 + kOffset;
    h.best_category = "person";
    h.confidence = 0.9;
    h.seen = true;
    h.seen_as = "person";
    h.first_heard_utime = h.settled_utime = -1;
    h.first_seen_utime = static_cast<int64_t>(std::llround(kFirstSeen * kDt * 1e6));
    message.hypotheses.push_back(h);
  }
  message.num_hypotheses = static_cast<int32_t>(message.hypotheses.size());
  return message;
}

// The world publishes GT_OBJECTS every tick here (the walker moves every
// tick); with keyframe_ticks > 0 the hypotheses go out as keyframes and changes.
void writeWalkerLog(const std::string& path, int keyframe_ticks) {
  lcm::LogFile log(path, "w");
  ASSERT_TRUE(log.good());
  hypotheses_t keyframe{};
  for (int k = 0; k < kTicks; ++k) {
    const int64_t stamp = 1'700'000'000'000'000 + k * 10'000;
    write(log, channels::kGroundTruth, sceneOf(k), stamp);
    robot_state_t robot{};
    robot.utime = sceneOf(k).utime;
    robot.tick = k;
    robot.x = 1;
    robot.y = 1;
    robot.radius = 0.35;
    write(log, channels::kRobotState, robot, stamp + 1);
    const hypotheses_t hypotheses = hypothesesOf(k);
    if (keyframe_ticks <= 0 || k % keyframe_ticks == 0) {
      write(log, channels::kHypotheses, hypotheses, stamp + 2);
      keyframe = hypotheses;
    }
    if (keyframe_ticks > 0)
      write(log, channels::kHypothesisChanges, wire::changesSince(keyframe, hypotheses), stamp + 2);
  }
}

class WalkerReport : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("beft_report_walker_" + std::to_string(::getpid()) + "_" +
                                       std::to_string(GetParam()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    log_path = (dir / "run.lcmlog").string();
    writeWalkerLog(log_path, GetParam());
  }
  void TearDown() override { fs::remove_all(dir); }

  fs::path dir;
  std::string log_path;
};

TEST_P(WalkerReport, APersonFoundWhileWalkingHasTheErrorOfItsEstimateAtThatTime) {
  const RunRecord record = readRunLog(log_path);
  ASSERT_EQ(record.truth_positions.at("walker").size(), static_cast<size_t>(kTicks));  // moved every tick
  EXPECT_EQ(record.truth_positions.at("wall").size(), 1u);                           // never moved
  const RunReport report = scoreRun(record, ScoringOptions{});
  ASSERT_EQ(report.victims.size(), 1u);
  const VictimEntry& v = report.victims[0];
  EXPECT_EQ(v.object, "walker");
  EXPECT_NEAR(v.found_at_s, kFirstSeen * kDt, 1e-6);
  EXPECT_NEAR(v.placed_at_s, kLastSeen * kDt, 1e-6);     // last tracked at 3 s
  EXPECT_NEAR(v.true_x, walkerX(kLastSeen), 1e-9);      // where it was then
  EXPECT_NEAR(v.error_m, kOffset, 1e-9);                // not the 4.9 m it walked on
  const double walked_on = walkerX(kTicks - 1) - walkerX(kLastSeen);
  EXPECT_GT(std::hypot(walked_on, kOffset), 4.0);       // what the end-of-run truth would have said
  const auto json = toJson(report);
  EXPECT_NEAR(json["victims"][0]["error_m"].get<double>(), kOffset, 1e-3);
  EXPECT_NEAR(json["victims"][0]["placed_at_s"].get<double>(), kLastSeen * kDt, 1e-3);
}

// Whole lists every tick, and keyframes every 7 ticks with changes between.
INSTANTIATE_TEST_SUITE_P(HypothesesAsSent, WalkerReport, ::testing::Values(0, 7));

TEST(TruthAt, TheLastPublishedPositionUpToTheTick) {
  RunRecord record;
  record.truth_positions["p"] = {{2, 1.0, 1.0}, {5, 2.0, 1.0}};
  EXPECT_FALSE(record.truthAt("p", 1).has_value());  // not published yet
  EXPECT_DOUBLE_EQ(record.truthAt("p", 2)->x, 1.0);
  EXPECT_DOUBLE_EQ(record.truthAt("p", 4)->x, 1.0);
  EXPECT_DOUBLE_EQ(record.truthAt("p", 5)->x, 2.0);
  EXPECT_DOUBLE_EQ(record.truthAt("p", 99)->x, 2.0);
  EXPECT_FALSE(record.truthAt("q", 5).has_value());
}

}  // namespace
}  // namespace beft::report

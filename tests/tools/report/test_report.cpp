// The run report on a small LCM log written here, with known ground truth,
// hypotheses and robot states: the scores in report.json, and the pictures.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include <beft/done_t.hpp>
#include <beft/dynamic_weights_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/hypothesis_changes_t.hpp>
#include <beft/process_rejects_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/run_status_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/task_stack_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/wire/hypothesis_changes.hpp"
#include "lib/report/map_picture.hpp"
#include "lib/wire/obstacle_map_codec.hpp"
#include "lib/report/report_files.hpp"
#include "lib/report/report_json.hpp"
#include "lib/report/run_record.hpp"
#include "lib/report/run_scoring.hpp"
#include "lib/report/weights_picture.hpp"
#include "tests/tools/report/log_events.hpp"

namespace beft::report {
namespace {

namespace fs = std::filesystem;

constexpr double kDt = 0.1;
constexpr int kTicks = 60;  // 6 s

fs::path scratchDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("beft_report_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

using report_test::write;

scene_object_t object(const std::string& id, const std::string& label, double x, double y, int8_t shape) {
  scene_object_t o{};
  o.id = id;
  o.label = label;
  o.activity = "idle";
  o.x = x;
  o.y = y;
  o.shape = shape;
  if (shape == scene_object_t::SHAPE_BOX) {
    o.size_x = 4;
    o.size_y = 0.2;
    o.size_z = 2.5;
    o.yaw = 90;
  } else if (shape == scene_object_t::SHAPE_CYLINDER) {
    o.radius = 0.3;
    o.size_x = o.size_y = 0.6;
    o.size_z = 1.8;
  }
  return o;
}

hypothesis_t hypothesis(const std::string& id, double x, double y, const std::string& best, double confidence) {
  hypothesis_t h{};
  h.object_id = id;
  h.x = x;
  h.y = y;
  h.best_category = best;
  h.confidence = confidence;
  h.num_categories = 0;
  h.first_heard_utime = h.first_seen_utime = h.settled_utime = -1;
  return h;
}

// A 6 s run in a 30 x 20 m yard: victim1 (behind wall1) is heard at 1 s and
// seen (verified) at 3 s; the radio sounds like a person and is seen as a
// siren at 4 s (falsified); victim2 is never perceived; the robot drives
// 0.1 m per tick along +x; DW weights and the task over time. With
// keyframe_ticks > 0 the hypotheses go out as fusion sends them now: the
// whole list every keyframe_ticks ticks, the changes since at every tick.
void writeRunLog(const std::string& path, int keyframe_ticks = 0) {
  lcm::LogFile log(path, "w");
  hypotheses_t keyframe{};
  ASSERT_TRUE(log.good());
  const int64_t wall0 = 1'700'000'000'000'000;
  for (int k = 0; k < kTicks; ++k) {
    const int64_t utime = static_cast<int64_t>(std::llround(k * kDt * 1e6));
    const int64_t stamp = wall0 + k * 10'000;  // 10 ms of wall time per tick
    scene_objects_t scene{};
    scene.utime = utime;
    scene.tick = k;
    scene.world_width = 30;
    scene.world_height = 20;
    scene.scenario = "testyard";
    scene.dt = kDt;
    scene.duration = 120;
    scene.categories = {"person", "car", "siren", "wall", "fire"};
    scene.num_categories = 5;
    scene.objects = {object("victim1", "person", 12, 8, scene_object_t::SHAPE_CYLINDER),
                     object("wall1", "wall", 10, 8, scene_object_t::SHAPE_BOX),
                     object("radio", "siren", 20, 15, scene_object_t::SHAPE_BOX),
                     object("victim2", "person", 5, 15, scene_object_t::SHAPE_CYLINDER)};
    scene.objects[2].has_acoustic = true;
    scene.objects[2].acoustic_label = "person";
    scene.num_objects = static_cast<int32_t>(scene.objects.size());
    write(log, channels::kGroundTruth, scene, stamp);

    robot_state_t robot{};
    robot.utime = utime;
    robot.tick = k;
    robot.x = 2 + 0.1 * k;
    robot.y = 2;
    robot.yaw = 0;
    robot.head_yaw = k < 30 ? 0 : 45;
    robot.radius = 0.35;
    robot.path_length = 0.1 * k;
    robot.collisions = k >= 50 ? 1 : 0;
    write(log, channels::kRobotState, robot, stamp + 1);

    const double t = k * kDt;
    hypotheses_t hypotheses{};
    hypotheses.utime = utime;
    hypotheses.tick = k;
    if (t >= 1.0 - 1e-9) {
      hypothesis_t v = hypothesis("victim1", 12.3, 8.4, "person", t >= 3.0 - 1e-9 ? 0.95 : 0.55);
      v.heard = true;
      v.heard_as = "person";
      v.first_heard_utime = 1'000'000;
      if (t >= 3.0 - 1e-9) {
        v.seen = v.verified = true;
        v.seen_as = "person";
        v.first_seen_utime = v.settled_utime = 3'000'000;
      }
      hypotheses.hypotheses.push_back(v);
      hypothesis_t r = hypothesis("radio", 20.2, 15.1, t >= 4.0 - 1e-9 ? "siren" : "person", 0.8);
      r.heard = true;
      r.heard_as = "person";
      if (t >= 4.0 - 1e-9) {
        r.seen = r.falsified = true;
        r.seen_as = "siren";
        r.settled_utime = 4'000'000;
      }
      hypotheses.hypotheses.push_back(r);
    }
    hypotheses.num_hypotheses = static_cast<int32_t>(hypotheses.hypotheses.size());
    if (keyframe_ticks <= 0 || k % keyframe_ticks == 0) {
      write(log, channels::kHypotheses, hypotheses, stamp + 2);
      keyframe = hypotheses;
    }
    if (keyframe_ticks > 0) write(log, channels::kHypothesisChanges, wire::changesSince(keyframe, hypotheses), stamp + 2);

    dynamic_weights_t weights{};
    weights.utime = utime;
    weights.tick = k;
    weights.viewing_direction = k < 30 ? 0 : 45;
    weights.current_task = k < 20 ? "explore" : "verify victim1";
    weights.attended_object = t >= 1.5 ? "victim1" : "";
    if (t >= 1.0 - 1e-9) {
      object_weight_t w{};
      w.object_id = "victim1";
      w.weight = std::min(1.0, 0.75 + 0.05 * (t - 1.0));
      weights.weights.push_back(w);
      w.object_id = "radio";
      w.weight = 0.5;
      weights.weights.push_back(w);
    }
    weights.num_weights = static_cast<int32_t>(weights.weights.size());
    write(log, channels::kDynamicWeights, weights, stamp + 3);
  }
  // The final obstacle map: free left part, the wall occupied, the rest unknown.
  planners::ObstacleCells cells;
  cells.width = 300;
  cells.height = 200;
  cells.resolution = 0.1;
  cells.cells.assign(300 * 200, obstacle_map_t::CELL_UNKNOWN);
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 150; ++x) cells.cells[y * 300 + x] = obstacle_map_t::CELL_FREE;
  for (int y = 60; y < 100; ++y) cells.cells[y * 300 + 100] = obstacle_map_t::CELL_OCCUPIED;
  write(log, channels::kObstacleMap, planners::makeObstacleMap(cells, obstacle_map_t::ENCODING_RLE, 5'900'000, 59),
        1'700'000'000'000'000 + kTicks * 10'000);
  run_status_t stop{};
  stop.utime = 5'900'000;
  stop.tick = 59;
  stop.state = run_status_t::STATE_FINISHED;
  stop.message = "nothing left to explore";
  write(log, channels::kStopRequest, stop, 1'700'000'000'000'000 + kTicks * 10'000 + 1);
}

class ReportFromLog : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = scratchDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    log_path = (dir / "run.lcmlog").string();
    writeRunLog(log_path);
  }
  void TearDown() override { fs::remove_all(dir); }

  fs::path dir;
  std::string log_path;
};

TEST_F(ReportFromLog, ReadsWhatTheRunRecorded) {
  const RunRecord record = readRunLog(log_path);
  EXPECT_EQ(record.scenario_name, "testyard");
  EXPECT_EQ(record.robot.size(), static_cast<size_t>(kTicks));
  EXPECT_NEAR(record.simTime(), (kTicks - 1) * kDt, 1e-9);
  EXPECT_EQ(record.truth.size(), 4u);
  ASSERT_TRUE(record.obstacle_map.has_value());
  EXPECT_EQ(record.obstacle_map->width, 300);
  EXPECT_EQ(record.stop_reason, "nothing left to explore");
  EXPECT_EQ(record.weights.size(), static_cast<size_t>(kTicks));
  EXPECT_TRUE(record.rejected.empty());
  EXPECT_EQ(record.log_damage, "");
}

TEST_F(ReportFromLog, HypothesesSentAsKeyframesAndChangesReadAsTheWholeListOfEveryTick) {
  const std::string changes_path = (dir / "changes.lcmlog").string();
  writeRunLog(changes_path, 20);
  const RunRecord whole = readRunLog(log_path);
  const RunRecord changes = readRunLog(changes_path);
  EXPECT_TRUE(changes.rejected.empty());
  ASSERT_EQ(changes.hypotheses.size(), whole.hypotheses.size());
  for (std::size_t i = 0; i < whole.hypotheses.size(); ++i) {
    EXPECT_DOUBLE_EQ(changes.hypotheses[i].t, whole.hypotheses[i].t);
    ASSERT_EQ(changes.hypotheses[i].hypotheses.size(), whole.hypotheses[i].hypotheses.size()) << i;
    for (std::size_t j = 0; j < whole.hypotheses[i].hypotheses.size(); ++j) {
      const auto& a = whole.hypotheses[i].hypotheses[j];
      const auto& b = changes.hypotheses[i].hypotheses[j];
      EXPECT_EQ(b.object_id, a.object_id);
      EXPECT_EQ(b.best_category, a.best_category);
      EXPECT_EQ(b.verified, a.verified);
      EXPECT_EQ(b.falsified, a.falsified);
      EXPECT_DOUBLE_EQ(b.confidence, a.confidence);
      EXPECT_DOUBLE_EQ(b.settled_s, a.settled_s);
    }
  }
  const RunReport report = scoreRun(changes, ScoringOptions{});
  ASSERT_EQ(report.victims.size(), 1u);
  EXPECT_NEAR(report.victims[0].found_at_s, 3.0, 1e-6);
  ASSERT_EQ(report.falsified.size(), 1u);
}

TEST_F(ReportFromLog, ScoresVictimsFalsifiedAndMissed) {
  const RunRecord record = readRunLog(log_path);
  ScoringOptions options;
  const RunReport report = scoreRun(record, options);
  ASSERT_EQ(report.victims.size(), 1u);
  const VictimEntry& v = report.victims[0];
  EXPECT_EQ(v.object, "victim1");
  EXPECT_NEAR(v.x, 12.3, 1e-9);
  EXPECT_NEAR(v.error_m, 0.5, 1e-9);  // (0.3, 0.4) off
  EXPECT_NEAR(v.confidence, 0.95, 1e-9);
  EXPECT_TRUE(v.verified);
  EXPECT_NEAR(v.found_at_s, 3.0, 1e-6);  // heard at 1 s does not count: seen at 3 s
  ASSERT_EQ(report.falsified.size(), 1u);
  EXPECT_EQ(report.falsified[0].object, "radio");
  EXPECT_EQ(report.falsified[0].heard_as, "person");
  EXPECT_EQ(report.falsified[0].seen_as, "siren");
  EXPECT_EQ(report.missed, std::vector<std::string>{"victim2"});
  EXPECT_FALSE(report.completed);  // victim2 was never found
  EXPECT_TRUE(report.false_alarms.empty());
  EXPECT_TRUE(report.unsettled.empty());
  EXPECT_EQ(report.persons, 2);
  EXPECT_EQ(report.ticks, kTicks);
  EXPECT_NEAR(report.path_length_m, 5.9, 1e-9);
  EXPECT_EQ(report.collisions, 1);
  EXPECT_NEAR(report.wall_time_s, 0.6 + 1e-6, 1e-6);  // log timestamps: 10 ms per tick
  EXPECT_NEAR(report.ticks_per_s, kTicks / report.wall_time_s, 1e-6);
  EXPECT_EQ(report.end_reason, "nothing left to explore");

  options.wall_time_s = 2.0;  // as the runner measured it
  EXPECT_NEAR(scoreRun(record, options).ticks_per_s, kTicks / 2.0, 1e-9);
  options.person_confidence = 0.99;  // stricter than the fused confidence
  EXPECT_TRUE(scoreRun(record, options).victims.empty());
}

TEST_F(ReportFromLog, TicksPerSecondCountTheLockstepLoopAndSurviveALostRobotState) {
  // The same run with its firings: FIRE first at 0.10 s, the last DONE at 0.50 s.
  {
    lcm::LogFile log(log_path, "a");
    fire_t fire{};
    fire.expert = "world";
    done_t done{};
    done.expert = "tasks";
    write(log, channels::kFire, fire, 1'700'000'000'100'000);
    write(log, channels::kDone, done, 1'700'000'000'300'000);
    write(log, channels::kDone, done, 1'700'000'000'500'000);
  }
  RunRecord record = readRunLog(log_path);
  EXPECT_NEAR(record.tickingSpan(), 0.4, 1e-9);
  record.robot.erase(record.robot.begin() + 10);  // a robot state the recorder lost
  ScoringOptions options;
  options.wall_time_s = 2.0;  // start and stop of every process included
  const RunReport report = scoreRun(record, options);
  EXPECT_EQ(report.ticks, kTicks);
  EXPECT_NEAR(report.ticking_time_s, 0.4, 1e-9);
  EXPECT_NEAR(report.ticks_per_s, kTicks / 0.4, 1e-6);
  EXPECT_NEAR(report.realtime_factor, report.sim_time_s / 0.4, 1e-6);
  EXPECT_NEAR(report.overall_realtime_factor, report.sim_time_s / 2.0, 1e-6);
  const auto json = toJson(report);
  EXPECT_NEAR(json.at("ticking_time_s").get<double>(), 0.4, 1e-9);
  EXPECT_NEAR(json.at("overall_realtime_factor").get<double>(), report.sim_time_s / 2.0, 0.051);
  std::ostringstream summary;
  printSummary(report, summary);
  EXPECT_NE(summary.str().find("0.40 s of lockstep loop"), std::string::npos) << summary.str();
  EXPECT_NE(summary.str().find("2.00 s in all"), std::string::npos) << summary.str();
}

TEST_F(ReportFromLog, AHeardButUnseenPersonIsNotAVictim) {
  RunRecord record = readRunLog(log_path);
  // Cut the run at 2 s: victim1 is heard (as a person) but not yet seen.
  while (!record.hypotheses.empty() && record.hypotheses.back().t > 2.0) record.hypotheses.pop_back();
  record.hypotheses.back().hypotheses[0].confidence = 0.9;
  const RunReport report = scoreRun(record, ScoringOptions{});
  EXPECT_TRUE(report.victims.empty());
  EXPECT_EQ(report.missed.size(), 2u);
  EXPECT_EQ(report.unsettled, (std::vector<std::string>{"victim1", "radio"}));
}

TEST_F(ReportFromLog, MatchesByPositionWhenTheIdNamesNoPerson) {
  RunRecord record = readRunLog(log_path);
  auto& final = record.hypotheses.back().hypotheses;
  final[0].object_id = "track7";  // a fusion that keys hypotheses its own way
  const RunReport report = scoreRun(record, ScoringOptions{});
  ASSERT_EQ(report.victims.size(), 1u);
  EXPECT_EQ(report.victims[0].object, "victim1");
  EXPECT_EQ(report.victims[0].hypothesis, "track7");
  final[0].x = 25;  // far from every person: a false alarm
  const RunReport far = scoreRun(record, ScoringOptions{});
  EXPECT_TRUE(far.victims.empty());
  ASSERT_EQ(far.false_alarms.size(), 1u);
  EXPECT_EQ(far.false_alarms[0].hypothesis, "track7");
}

TEST_F(ReportFromLog, WritesTheJsonAndReadablePictures) {
  const RunRecord record = readRunLog(log_path);
  const RunReport report = scoreRun(record, ScoringOptions{});
  const fs::path out = dir / "out";
  writeReportFiles(record, report, out.string());

  std::ifstream file(out / "report.json");
  ASSERT_TRUE(file.good());
  const nlohmann::json json = nlohmann::json::parse(file);
  for (const char* key : {"scenario", "completed", "sim_time_s", "wall_time_s", "ticks", "ticks_per_s",
                          "path_length_m", "collisions", "victims", "falsified", "missed"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_EQ(json["scenario"], "testyard");
  EXPECT_EQ(json["completed"], false);
  ASSERT_EQ(json["victims"].size(), 1u);
  for (const char* key : {"object", "x", "y", "error_m", "confidence", "verified", "found_at_s"})
    EXPECT_TRUE(json["victims"][0].contains(key)) << key;
  EXPECT_EQ(json["victims"][0]["object"], "victim1");
  EXPECT_NEAR(json["victims"][0]["error_m"].get<double>(), 0.5, 1e-3);
  ASSERT_EQ(json["falsified"].size(), 1u);
  for (const char* key : {"object", "x", "y", "heard_as", "seen_as"})
    EXPECT_TRUE(json["falsified"][0].contains(key)) << key;
  EXPECT_EQ(json["missed"], nlohmann::json::array({"victim2"}));

  const cv::Mat map = cv::imread((out / "map.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(map.empty());
  const MapLayout layout = mapLayout(30, 20);
  EXPECT_EQ(map.cols, layout.width);
  EXPECT_EQ(map.rows, layout.height);
  // The robot's path is drawn where the robot drove (x from 2 to 7.9 at y = 2).
  const cv::Vec3b on_path = map.at<cv::Vec3b>(layout.toPixel(4.5, 2.0));
  EXPECT_GT(on_path[0], 150);  // blue-ish path colour (BGR)
  EXPECT_LT(on_path[2], 80);
  // The obstacle map shows: unknown on the right, free on the left (inside the world, away from drawings).
  const cv::Vec3b unknown = map.at<cv::Vec3b>(layout.toPixel(27.3, 3.3));
  const cv::Vec3b free = map.at<cv::Vec3b>(layout.toPixel(7.3, 11.3));
  EXPECT_LT(unknown[1], free[1]);

  const cv::Mat weights = cv::imread((out / "weights.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(weights.empty());
  EXPECT_EQ(weights.cols, kWeightsPictureWidth);
  EXPECT_EQ(weights.rows, kWeightsPictureHeight);
  cv::Scalar mean, stddev;
  cv::meanStdDev(weights, mean, stddev);
  EXPECT_GT(stddev[0], 10);  // something was drawn
}

TEST_F(ReportFromLog, SummaryNamesTheVictimAndTheMiss) {
  const RunReport report = scoreRun(readRunLog(log_path), ScoringOptions{});
  std::ostringstream text;
  printSummary(report, text);
  EXPECT_NE(text.str().find("victim1"), std::string::npos);
  EXPECT_NE(text.str().find("missed:      victim2"), std::string::npos);
  EXPECT_NE(text.str().find("ticks/s"), std::string::npos);
}

process_rejects_t rejects(const std::string& process, int32_t pid, int64_t unauthenticated, int64_t malformed) {
  process_rejects_t account{};
  account.process = process;
  account.pid = pid;
  account.host = "here";
  account.unauthenticated = unauthenticated;
  account.malformed = malformed;
  return account;
}

// The processes' own accounts of what they refused (a log keeps no tags):
// the last of each process instance, a restart's added, in report.json and
// the summary.
TEST_F(ReportFromLog, CountsWhatEachProcessRefusedWithoutAValidTag) {
  {
    lcm::LogFile log(log_path, "a");
    ASSERT_TRUE(log.good());
    const int64_t at = 1'700'000'000'000'000 + kTicks * 10'000 + 10;
    write(log, channels::kProcessRejects, rejects("tasks", 100, 5, 0), at);
    write(log, channels::kProcessRejects, rejects("tasks", 100, 40, 1), at + 1);  // the same process, later
    write(log, channels::kProcessRejects, rejects("tasks", 200, 2, 0), at + 2);   // restarted
    write(log, channels::kProcessRejects, rejects("vision", 300, 7, 0), at + 3);
    write(log, channels::kProcessRejects, rejects("world", 400, 0, 9), at + 4);  // malformed only
  }
  const RunRecord record = readRunLog(log_path);
  ASSERT_EQ(record.process_rejects.count("tasks"), 1u);
  EXPECT_EQ(record.process_rejects.at("tasks").unauthenticated, 42);
  EXPECT_EQ(record.process_rejects.at("tasks").malformed, 1);
  EXPECT_EQ(record.process_rejects.at("world").malformed, 9);
  const RunReport report = scoreRun(record, ScoringOptions{});
  const nlohmann::json json = toJson(report);
  EXPECT_EQ(json["unauthenticated_total"], 49);
  EXPECT_EQ(json["unauthenticated_messages"]["tasks"], 42);
  EXPECT_EQ(json["unauthenticated_messages"]["vision"], 7);
  EXPECT_FALSE(json["unauthenticated_messages"].contains("world"));
  std::ostringstream text;
  printSummary(report, text);
  EXPECT_NE(text.str().find("refused:     49 message(s) without a valid tag of the run's key (tasks 42, vision 7)"),
            std::string::npos)
      << text.str();
}

TEST_F(ReportFromLog, AnUnkeyedRunRefusedNothingForWantOfATag) {
  const RunReport report = scoreRun(readRunLog(log_path), ScoringOptions{});
  const nlohmann::json json = toJson(report);
  EXPECT_EQ(json["unauthenticated_total"], 0);
  EXPECT_TRUE(json["unauthenticated_messages"].empty());
  std::ostringstream text;
  printSummary(report, text);
  EXPECT_EQ(text.str().find("refused:"), std::string::npos);
}

TEST(ReportErrors, ANonLogFileIsRefusedWithItsName) {
  const fs::path dir = scratchDir("errors");
  const fs::path path = dir / "not_a_log.txt";
  std::ofstream(path) << "hello";
  try {
    readRunLog(path.string());
    FAIL() << "expected a ReportError";
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find("not_a_log.txt"), std::string::npos);
  }
  EXPECT_THROW(readRunLog((dir / "missing.lcmlog").string()), ReportError);
  fs::remove_all(dir);
}

TEST(ReportCommand, BadInputExitsNonZeroWithAMessage) {
  const fs::path dir = scratchDir("command");
  const std::string command = std::string(BEFT_REPORT_BINARY) + " " + (dir / "missing.lcmlog").string() +
                              " --out " + (dir / "out").string() + " 2> " + (dir / "err.txt").string();
  const int status = std::system(command.c_str());
  EXPECT_NE(status, 0);
  std::ifstream err(dir / "err.txt");
  const std::string message((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  EXPECT_NE(message.find("missing.lcmlog"), std::string::npos) << message;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace beft::report

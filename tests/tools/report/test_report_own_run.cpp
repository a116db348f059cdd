// A log with run ids is its run's: the report takes its figures (ticks, why
// the run ended, the times) from the run's own channels only, so messages
// forged on a channel without an id, or on another run's (a replayed log,
// another run sharing the URL), change none of them and are counted.
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <beft/fire_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/run_status_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/report/run_record.hpp"
#include "lib/report/run_scoring.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/wire/run_identity.hpp"
#include "tests/tools/report/log_events.hpp"

namespace beft::report {
namespace {

namespace fs = std::filesystem;

constexpr int64_t kRun = 0x5a5a;
constexpr int64_t kOtherRun = 0x6b6b;
constexpr int kTicks = 10;
constexpr int64_t kWall0 = 1'700'000'000'000'000;

using report_test::write;

robot_state_t robotAt(int64_t tick) {
  robot_state_t robot{};
  robot.utime = tick * 100'000;
  robot.tick = tick;
  robot.x = 2 + 0.1 * static_cast<double>(tick);
  robot.y = 2;
  robot.radius = 0.35;
  robot.path_length = 0.1 * static_cast<double>(tick);
  return robot;
}

run_status_t status(int64_t tick, int8_t state, const std::string& message) {
  run_status_t s{};
  s.utime = tick * 100'000;
  s.tick = tick;
  s.state = state;
  s.message = message;
  return s;
}

// The run's ten ticks on its own channels; between them, what others sent:
// on plain channels and on another run's, robot states of far later ticks
// and statuses that would end the run otherwise. Returns the forged count.
int writeLogWithForgeries(const std::string& path) {
  lcm::LogFile log(path, "w");
  EXPECT_TRUE(log.good());
  const auto own = [](const std::string& channel) { return wire::runChannel(channel, kRun); };
  const auto other = [](const std::string& channel) { return wire::runChannel(channel, kOtherRun); };
  const std::string robot_channel(channels::kRobotState.name), status_channel(channels::kRunStatus.name),
      stop_channel(channels::kStopRequest.name);
  int forged = 0;
  fire_t fire{};
  fire.expert = "world";
  fire.transition = "t_world";
  write(log, own(channels::kFire.name), fire, kWall0);  // the run's arbiter: the log's run
  scene_objects_t scene{};
  scene.scenario = "ownrun";
  scene.world_width = 30;
  scene.world_height = 20;
  scene.dt = 0.1;
  scene.duration = 1;
  write(log, own(channels::kGroundTruth.name), scene, kWall0 + 1);
  for (int k = 0; k < kTicks; ++k) {
    const int64_t stamp = kWall0 + 1'000 + k * 10'000;
    write(log, own(robot_channel), robotAt(k), stamp);
    write(log, own(status_channel), status(k, run_status_t::STATE_RUNNING, "running"), stamp + 1);
    write(log, robot_channel, robotAt(1000 + k), stamp + 2);
    write(log, other(robot_channel), robotAt(5000 + k), stamp + 3);
    forged += 2;
  }
  // Later than the run's end, so that they would win were they taken.
  const int64_t end = kWall0 + 1'000 + kTicks * 10'000;
  write(log, own(status_channel), status(kTicks - 1, run_status_t::STATE_FINISHED, "finished after 10 ticks"), end);
  write(log, status_channel, status(99'999, run_status_t::STATE_FAILED, "forged on a plain channel"), end + 60'000'000);
  write(log, other(status_channel), status(99'999, run_status_t::STATE_FAILED, "forged in another run"), end + 60'000'001);
  write(log, stop_channel, status(99'999, run_status_t::STATE_FINISHED, "forged stop"), end + 60'000'002);
  write(log, other(stop_channel), status(99'999, run_status_t::STATE_FINISHED, "forged stop"), end + 60'000'003);
  return forged + 4;
}

class ReportOfItsOwnRun : public ::testing::Test {
 protected:
  void SetUp() override {
    unsetenv("BEFT_RUN_ID");  // the log's own run, as beft-report run by hand finds it
    dir = fs::temp_directory_path() / ("beft_report_own_run_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    log_path = (dir / "run.lcmlog").string();
    forged = writeLogWithForgeries(log_path);
  }
  void TearDown() override { fs::remove_all(dir); }

  fs::path dir;
  std::string log_path;
  int forged = 0;
};

TEST_F(ReportOfItsOwnRun, ForgedStatusesAndStatesChangeNoFigure) {
  ASSERT_EQ(wire::runOfLog(log_path), kRun);
  const RunRecord record = readRunLog(log_path);
  ASSERT_EQ(record.robot.size(), static_cast<size_t>(kTicks));
  EXPECT_EQ(record.robot.front().tick, 0);
  EXPECT_EQ(record.robot.back().tick, kTicks - 1);
  EXPECT_EQ(record.tickCount(), kTicks);
  EXPECT_EQ(record.run_status, "finished after 10 ticks");
  EXPECT_EQ(record.stop_reason, "");
  EXPECT_EQ(record.other_run_messages, forged);
  EXPECT_LT(record.wallSpan(), 1.0) << "a forged message's time was taken";
  const RunReport report = scoreRun(record, ScoringOptions{});
  EXPECT_EQ(report.ticks, kTicks);
  EXPECT_EQ(report.end_reason, "finished after 10 ticks");
}

TEST_F(ReportOfItsOwnRun, BeftReportWritesTheRunsOwnFigures) {
  const std::string out = (dir / "out").string();
  const std::string command =
      std::string(BEFT_REPORT_BINARY) + " " + log_path + " --out " + out + " --quiet 2> " + (dir / "err.txt").string();
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::ifstream in(out + "/report.json");
  const nlohmann::json json = nlohmann::json::parse(in);
  EXPECT_EQ(json["ticks"].get<int64_t>(), kTicks);
  EXPECT_EQ(json["end_reason"].get<std::string>(), "finished after 10 ticks");
  EXPECT_EQ(json["other_run_messages"].get<int64_t>(), forged);
}

}  // namespace
}  // namespace beft::report

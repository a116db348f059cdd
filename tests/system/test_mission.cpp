// The mission end to end, as separate processes over LCM (./beft run): the
// shipped scenarios' promises, checked from each run's log and report.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include <beft/dynamic_weights_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/plan_result_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/task_command_t.hpp>

#include "lib/model/model.hpp"
#include "tests/system/run_digests.hpp"
#include "tests/system/run_support.hpp"

using namespace beft::system_test;

namespace {

struct MissionRun {
  std::string dir;
  ProgramResult result;
  std::vector<LoggedMessage> log;
  nlohmann::json report;
};

// Each scenario runs once per test program; the tests share the result.
const MissionRun& missionRun(const std::string& scenario, const std::string& extra_args = "") {
  static std::map<std::string, MissionRun> runs;
  const std::string key = scenario + " " + extra_args;
  auto it = runs.find(key);
  if (it != runs.end()) return it->second;
  MissionRun run;
  run.dir = makeTempDir("mission_" + scenario);
  run.result = runCommand(binDir() + "/beft-run " + sourceDir() + "/scenarios/" + scenario +
                              ".xml --out " + run.dir + " " + extra_args,
                          600);
  try {
    run.log = readLog(run.dir + "/run.lcmlog");
    run.report = readJson(run.dir + "/report.json");
  } catch (const std::exception& e) {
    run.result.output += std::string("\n[test] ") + e.what();
  }
  return runs.emplace(key, std::move(run)).first->second;
}

const nlohmann::json* victimEntry(const nlohmann::json& report, const std::string& id) {
  for (const auto& v : report["victims"])
    if (v["object"] == id) return &v;
  return nullptr;
}

double seconds(int64_t utime) { return static_cast<double>(utime) * 1e-6; }

}  // namespace

TEST(MissionYard, ThePapersPlannerAsPrintedCompletesTheMission) {
  // pf-paper: the robot traces the winning particle's own path h_W.
  const auto& run = missionRun("yard", "--planner pf-paper");
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  EXPECT_TRUE(run.report["completed"].get<bool>()) << run.report.dump(2);
  EXPECT_EQ(run.report["collisions"], 0);
  EXPECT_NE(victimEntry(run.report, "victim_hidden"), nullptr) << run.report.dump(2);
  EXPECT_NE(victimEntry(run.report, "victim_seen"), nullptr) << run.report.dump(2);
  // Its answers are dense: a waypoint per particle step, not a few taut corners.
  size_t waypoints = 0, answers = 0;
  for (const auto& result : messagesOn<beft::plan_result_t>(run.log, "PLAN_RESULT")) {
    if (!result.success) continue;
    EXPECT_EQ(result.planner, "pf-paper");
    waypoints += static_cast<size_t>(result.num_waypoints);
    ++answers;
  }
  ASSERT_GT(answers, 0u);
  EXPECT_GT(waypoints / answers, 20u);
}

TEST(MissionYard, EveryVictimFoundCloselyAndTheHiddenOneVerifiedWithoutCollision) {
  const auto& run = missionRun("yard");
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto& report = run.report;
  for (const char* key : {"scenario", "completed", "sim_time_s", "wall_time_s", "ticks", "ticks_per_s",
                          "path_length_m", "collisions", "victims", "falsified", "missed"})
    EXPECT_TRUE(report.contains(key)) << key;
  EXPECT_EQ(report["collisions"], 0);
  EXPECT_TRUE(report["missed"].empty()) << report.dump(2);
  for (const char* id : {"victim_seen", "victim_hidden"}) {
    const auto* victim = victimEntry(report, id);
    ASSERT_NE(victim, nullptr) << id << "\n" << report.dump(2);
    EXPECT_LE((*victim)["error_m"].get<double>(), 0.5) << id;
  }
  const auto* hidden = victimEntry(report, "victim_hidden");
  EXPECT_TRUE((*hidden)["verified"].get<bool>()) << report.dump(2);
  EXPECT_TRUE(report["completed"].get<bool>()) << report.dump(2);

  // Verified after the robot moved to see it: far from the start at that time.
  const double found_at = (*hidden)["found_at_s"].get<double>();
  double x = 2, y = 2;
  for (const auto& state : messagesOn<beft::robot_state_t>(run.log, "ROBOT_STATE"))
    if (seconds(state.utime) <= found_at) x = state.x, y = state.y;
  EXPECT_GT(std::hypot(x - 2, y - 2), 3.0) << "robot at (" << x << ", " << y << ") when it verified";
  std::printf("[yard] ticks per second: %.1f (%.1fx real time)\n", report["ticks_per_s"].get<double>(),
              report["ticks_per_s"].get<double>() * 0.1);
}

TEST(MissionPeek, HiddenVictimIsHeardFirstThenVerifiedByGoingAround) {
  const auto& run = missionRun("peek");
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto* victim = victimEntry(run.report, "victim");
  ASSERT_NE(victim, nullptr) << run.report.dump(2);
  EXPECT_TRUE((*victim)["verified"].get<bool>());
  EXPECT_LE((*victim)["error_m"].get<double>(), 0.5);
  int64_t first_heard = -1, first_seen = -1;
  for (const auto& hs : hypothesesOfEachTick(run.log))
    for (const auto& h : hs.hypotheses)
      if (h.object_id == "victim") first_heard = h.first_heard_utime, first_seen = h.first_seen_utime;
  ASSERT_GE(first_heard, 0);
  ASSERT_GE(first_seen, 0);
  EXPECT_LT(first_heard, first_seen);
  EXPECT_GT(run.report["path_length_m"].get<double>(), 3.0);
  // The outcome, as yard's: every person found, no collision, the mission completed.
  EXPECT_TRUE(run.report["completed"].get<bool>()) << run.report.dump(2);
  EXPECT_EQ(run.report["collisions"], 0) << run.report.dump(2);
  EXPECT_TRUE(run.report["missed"].empty()) << run.report.dump(2);
  EXPECT_EQ(run.report["victims"].size(), 1u) << run.report.dump(2);
  EXPECT_TRUE(run.report["falsified"].empty()) << run.report.dump(2);
}

TEST(MissionDecoy, RadioIsFalsifiedAndTheRealVictimReported) {
  const auto& run = missionRun("decoy");
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  EXPECT_EQ(victimEntry(run.report, "radio"), nullptr) << run.report.dump(2);
  bool radio_falsified = false;
  for (const auto& f : run.report["falsified"])
    if (f["object"] == "radio") {
      radio_falsified = true;
      EXPECT_EQ(f["heard_as"], "person");
      EXPECT_EQ(f["seen_as"], "siren");
    }
  EXPECT_TRUE(radio_falsified) << run.report.dump(2);
  EXPECT_EQ(run.report["falsified"].size(), 1u) << run.report.dump(2);
  // The outcome, as yard's: the one person found closely, no collision, the mission completed.
  const auto* victim = victimEntry(run.report, "victim");
  ASSERT_NE(victim, nullptr) << run.report.dump(2);
  EXPECT_LE((*victim)["error_m"].get<double>(), 0.5) << run.report.dump(2);
  EXPECT_EQ(run.report["victims"].size(), 1u) << run.report.dump(2);
  EXPECT_TRUE(run.report["missed"].empty()) << run.report.dump(2);
  EXPECT_EQ(run.report["collisions"], 0) << run.report.dump(2);
  EXPECT_TRUE(run.report["completed"].get<bool>()) << run.report.dump(2);
}

// The spec's curves for fig4_dw (spec/model.md, "Dynamic weighting, eq. 4"),
// written out per phase of the scenario, independently of the DW code: the
// weight of each object at DW step k (t = 0.5 k s).
double curveSpan(int t) { return std::log(std::min(t, 10)) / (2 * std::log(100.0)); }

double expectedWalker(int k) {
  if (k == 0) return 0.5;                                    // newly heard
  if (k < 20) return std::max(0.0, 0.25 - curveSpan(k));     // walking: falls from 0.25 to 0
  if (k < 50) return 0.75 + curveSpan(k - 19);               // yelling from 10 s: jumps to 0.75, rises to 1
  if (k < 60) return 0.75 - curveSpan(k - 49);               // stops at 25 s: from 0.75 to the residual 0.5
  return 0.75 + curveSpan(k - 59);                           // endangered by the spreading fire from 30 s
}

double expectedFire(int k) {
  if (k == 0) return 0.5;
  if (k < 60) return 0.5 - curveSpan(k);                     // burning: falls from 0.5 to 0.25
  return 0.75 + curveSpan(k - 59);                           // spreading from 30 s
}

TEST(MissionFig4, EveryWeightAtEveryStepIsTheSpecsCurve) {
  // The whole 45 s: the exploration expert keeps watching after everything is settled.
  const auto& run = missionRun("fig4_dw", "--set stop_when_done=0");
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  std::map<int64_t, beft::dynamic_weights_t> by_tick;
  for (const auto& message : messagesOn<beft::dynamic_weights_t>(run.log, "DYNAMIC_WEIGHTS")) by_tick[message.tick] = message;
  std::map<int64_t, beft::robot_state_t> robot_at;
  for (const auto& state : messagesOn<beft::robot_state_t>(run.log, "ROBOT_STATE")) robot_at[state.tick] = state;
  std::map<int64_t, std::pair<double, double>> walker_at;
  for (const auto& gt : messagesOn<beft::scene_objects_t>(run.log, "GT_OBJECTS"))
    for (const auto& o : gt.objects)
      if (o.id == "walker") walker_at[gt.tick] = {o.x, o.y};

  int steps_checked = 0, directions_checked = 0;
  for (int k = 0; k < 90; ++k) {
    const auto found = by_tick.find(5 * k);  // DW steps every 0.5 s = 5 ticks
    if (found == by_tick.end()) continue;    // a datagram the recorder lost
    std::map<std::string, double> weight;
    for (const auto& w : found->second.weights) weight[w.object_id] = w.weight;
    ASSERT_EQ(weight.size(), 2u) << "step " << k;
    EXPECT_NEAR(weight["walker"], expectedWalker(k), 1e-9) << "walker at t = " << 0.5 * k << " s";
    EXPECT_NEAR(weight["fire1"], expectedFire(k), 1e-9) << "fire1 at t = " << 0.5 * k << " s";
    ++steps_checked;
    // DW's viewing direction: towards the heaviest object at or above 0.75
    // (the walker wins the ties with the fire: first heard), none below.
    const double direction = found->second.viewing_direction;
    const bool walker_leads = expectedWalker(k) >= 0.75 - 1e-12;
    if (!walker_leads) {
      EXPECT_TRUE(std::isnan(direction)) << "t = " << 0.5 * k << " s: " << direction;
    } else if (robot_at.count(5 * k) && walker_at.count(5 * k)) {
      const auto& robot = robot_at[5 * k];
      const auto [wx, wy] = walker_at[5 * k];
      EXPECT_NEAR(direction, std::atan2(wy - robot.y, wx - robot.x) * 180 / M_PI, 1e-6) << "t = " << 0.5 * k << " s";
      ++directions_checked;
    }
  }
  EXPECT_GE(steps_checked, 80);
  EXPECT_GE(directions_checked, 40);

  // The turn-to reflexes, in order: the walker's yell, then at 30 s the
  // endangered walker and the spreading fire, in the order first heard.
  std::vector<std::pair<std::string, double>> reflexes;
  for (const auto& command : messagesOn<beft::task_command_t>(run.log, "TASK_COMMAND"))
    if (command.command == beft::task_command_t::COMMAND_PUSH && command.task.origin == "dw")
      reflexes.emplace_back(command.task.object_id, seconds(command.utime));
  ASSERT_EQ(reflexes.size(), 3u);
  EXPECT_EQ(reflexes[0], std::make_pair(std::string("walker"), 10.0));
  EXPECT_EQ(reflexes[1], std::make_pair(std::string("walker"), 30.0));
  EXPECT_EQ(reflexes[2], std::make_pair(std::string("fire1"), 30.0));

  // The head follows: it faces the walker soon after the yell.
  double best = 180;
  for (const auto& [tick, s] : robot_at) {
    if (seconds(s.utime) < 10.0 || seconds(s.utime) > 16.0 || !walker_at.count(tick)) continue;
    const auto [wx, wy] = walker_at[tick];
    best = std::min(best, std::abs(beft::model::azimuth(s.x, s.y, s.yaw + s.head_yaw, wx, wy)));
  }
  EXPECT_LT(best, 10.0) << "the head never faced the yelling walker";
}

TEST(MissionYard, TheConcurrentNetWritesExactlyTheMessagesOfThePapersSchedule) {
  // Experts started as soon as what they read is written (concurrent.pnml)
  // see the same inputs as level by level (default.pnml): every data message
  // of the run is the same, byte for byte.
  const auto& paper = missionRun("yard");
  const auto& concurrent = missionRun("yard", "--net " + sourceDir() + "/scenarios/nets/concurrent.pnml");
  ASSERT_EQ(concurrent.result.exit_code, 0) << concurrent.result.output;
  const DataComparison comparison = compareDataMessages(paper.log, concurrent.log);
  ASSERT_GT(comparison.expected, 5000u);
  EXPECT_TRUE(comparison.identical()) << comparison.first_difference;
  EXPECT_EQ(paper.report["ticks"], concurrent.report["ticks"]);
  EXPECT_EQ(paper.report["victims"], concurrent.report["victims"]);
}

namespace {

const std::string kDigestFile = sourceDir() + "/tests/system/data/data_digests.json";
const std::string kFingerprintFile = sourceDir() + "/tests/system/data/message_fingerprints.json";

}  // namespace

// The data messages of the shipped missions are pinned: a change meant to
// alter no message of a run (a refactoring, a speed-up) is checked against
// the build before it. Any difference fails at once, the first differing
// message named and decoded. A change that alters them on purpose re-pins
// them with build/bin/mission_digests (README.md) and says why in its commit.
TEST(MissionDigests, YardPeekAndDecoyWriteTheDataMessagesOfThePinnedBuild) {
  const nlohmann::json pinned = readJson(kDigestFile), fingerprints = readJson(kFingerprintFile);
  for (const std::string scenario : {"yard", "peek", "decoy"}) {
    const auto& run = missionRun(scenario);
    ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
    ASSERT_TRUE(pinned.contains(scenario)) << kDigestFile << " has no " << scenario;
    const std::string mismatch = digestMismatch(run.log, digestRun(run.log), pinned[scenario],
                                                fingerprints.value(scenario, nlohmann::json::object()));
    EXPECT_TRUE(mismatch.empty()) << scenario << ": " << mismatch;
  }
}

// A data message changed in a recorded run: the digest check and the run
// comparison both name it (channel, index, tick), not only notice it.
TEST(PlantedDifference, OneChangedDataMessageFailsTheDigestsAndTheComparisonAndIsNamed) {
  const auto original = readLog(sourceDir() + "/tests/system/data/peek_6_ticks.lcmlog");
  const RunDigests digests = digestRun(original);
  const nlohmann::json pins = digestsAsJson(digests), fingerprints = fingerprintsAsJson(digests);
  ASSERT_EQ(digestMismatch(original, digests, pins, fingerprints), "");
  ASSERT_TRUE(compareDataMessages(original, original).identical());

  // The third ROBOT_STATE (tick 2): one byte of its x changed.
  auto planted = original;
  int robot_states = 0;
  for (auto& message : planted)
    if (message.channel == "ROBOT_STATE" && robot_states++ == 2) message.data[8 + 16 + 3] ^= 0x01;
  ASSERT_GT(robot_states, 2);

  const std::string mismatch = digestMismatch(planted, digestRun(planted), pins, fingerprints);
  EXPECT_NE(mismatch.find("on 1 channel(s)"), std::string::npos) << mismatch;
  EXPECT_NE(mismatch.find("ROBOT_STATE message #2 (tick 2): differs"), std::string::npos) << mismatch;
  const DataComparison comparison = compareDataMessages(original, planted);
  EXPECT_FALSE(comparison.identical());
  EXPECT_NE(comparison.first_difference.find("ROBOT_STATE message #2 (tick 2"), std::string::npos)
      << comparison.first_difference;
  EXPECT_NE(comparison.first_difference.find("first differing field"), std::string::npos)
      << comparison.first_difference;
}

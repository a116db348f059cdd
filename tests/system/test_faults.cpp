// Faults a lab network brings, with real processes: a process killed at any
// tick, malformed traffic on the run's own channels, another run on the same
// URL, a damaged log. Each disturbed yard run must write exactly the data
// messages of the undisturbed one.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <beft/scene_objects_t.hpp>
#include <beft/scene_version_t.hpp>

#include "tests/system/run_support.hpp"

using namespace beft::system_test;

namespace {

constexpr int kTicks = 300;

// The recorder at the normal priority: what is compared is what it wrote,
// and a loaded machine (two runs, a flood) would otherwise starve it.
const std::string kRecorderInFront = "BEFT_BACKGROUND=0 ";

struct FaultRun {
  std::string dir;
  ProgramResult result;
  std::vector<LoggedMessage> log;
  nlohmann::json report;
};

FaultRun runScenario(const std::string& tag, const std::string& scenario, const std::string& extra_args) {
  FaultRun run;
  run.dir = makeTempDir("faults_" + tag);
  run.result = runCommand(kRecorderInFront + binDir() + "/beft-run " + scenario + " --max-ticks " +
                              std::to_string(kTicks) + " --out " + run.dir + " " + extra_args,
                          600);
  try {
    run.log = readLog(run.dir + "/run.lcmlog");
    run.report = readJson(run.dir + "/report.json");
  } catch (const std::exception& e) {
    run.result.output += std::string("\n[test] ") + e.what();
  }
  return run;
}

FaultRun runYard(const std::string& tag, const std::string& extra_args) {
  return runScenario(tag, sourceDir() + "/scenarios/yard.xml", extra_args);
}

const FaultRun& cleanRun() {
  static const FaultRun run = runYard("clean", "");
  return run;
}

std::string processLog(const FaultRun& run) { return runCommand("cat " + run.dir + "/processes.log", 10).output; }

// The ticks the arbiter ran, as it says when the run ends (the log may have
// lost the last ticks' datagrams).
int ticksRun(const FaultRun& run) {
  const std::string said = lineAfter(processLog(run), "[arbiter] [arbiter] info: FINISHED: finished after ");
  return said.empty() ? -1 : std::stoi(said);
}

// What a disturbed run's log holds besides the run's messages, left out
// (and counted) before the comparison.
enum class LeftOut {
  kNothing,
  kRefused,  // malformed traffic injected on the run's channels: the recorder logged it too; there must be some
};

// Every data message of `run` is the clean run's, none missing, none extra,
// none sent twice (a process restarted, or an arbiter resumed, repeats nothing).
void expectSameDataMessages(const FaultRun& run, const FaultRun& clean = cleanRun(),
                            LeftOut left_out = LeftOut::kNothing) {
  ASSERT_EQ(clean.result.exit_code, 0) << clean.result.output;
  std::size_t refused_in_clean = 0, repeats_in_clean = 0, count = 0;
  withoutRefused(clean.log, refused_in_clean);
  withoutRepeats(clean.log, repeats_in_clean);
  EXPECT_EQ(refused_in_clean, 0u);
  EXPECT_EQ(repeats_in_clean, 0u);
  std::vector<LoggedMessage> compared = run.log;
  if (left_out == LeftOut::kRefused) {
    compared = withoutRefused(run.log, count);
    EXPECT_GT(count, 0u) << "no injected message in the log";
    std::printf("[faults] %zu refused messages left out of the disturbed run\n", count);
  }
  std::size_t repeats = 0;
  withoutRepeats(compared, repeats);
  EXPECT_EQ(repeats, 0u) << "data messages sent twice";
  const DataComparison comparison = compareDataMessages(clean.log, compared);
  EXPECT_GT(comparison.expected, 1000u);
  EXPECT_EQ(ticksRun(run), ticksRun(clean)) << "the disturbed run ended elsewhere";
  EXPECT_TRUE(comparison.identical()) << comparison.first_difference;
}

// A run started in the background, and the URL and run id it prints.
struct BackgroundRun {
  pid_t pid = -1;
  FaultRun run;
  std::string url, run_id;
};

BackgroundRun startYard(const std::string& tag) {
  BackgroundRun background;
  background.run.dir = makeTempDir("faults_" + tag);
  const std::string out = background.run.dir + "/run_output.txt";
  background.pid = fork();
  if (background.pid == 0) {
    const std::string command = kRecorderInFront + binDir() + "/beft-run " + sourceDir() + "/scenarios/yard.xml --max-ticks " +
                                std::to_string(kTicks) + " --out " + background.run.dir + " > " + out + " 2>&1";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 3000 && (background.url.empty() || background.run_id.empty()); ++i) {  // up to a minute
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const auto text = runCommand("cat " + out, 5).output;
    const auto line = lineAfter(text, "[run] LCM ");
    if (!line.empty()) background.url = line.substr(0, line.find(';'));
    const auto started = lineAfter(text, "[launch] started ");
    if (const auto at = started.find(" as run "); at != std::string::npos) background.run_id = started.substr(at + 8);
  }
  return background;
}

void finish(BackgroundRun& background) {
  int status = 0;
  waitpid(background.pid, &status, 0);
  background.run.result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  background.run.result.output = runCommand("cat " + background.run.dir + "/run_output.txt", 5).output;
  // Other runs share this log: this run's messages are those of its id.
  background.run.log = readLog(background.run.dir + "/run.lcmlog", nullptr, background.run_id);
  background.run.report = readJson(background.run.dir + "/report.json");
}

// beft-inject in the background until killed.
pid_t inject(const std::string& arguments) {
  const pid_t pid = fork();
  if (pid == 0) {
    const std::string command = "exec " + binDir() + "/beft-inject " + arguments + " > /dev/null 2>&1";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

void stop(pid_t pid) {
  kill(pid, SIGTERM);
  waitpid(pid, nullptr, 0);
}

}  // namespace

class KilledProcess : public ::testing::TestWithParam<std::pair<const char*, int>> {};

TEST_P(KilledProcess, ResumesFromTheLogAndTheRunWritesTheSameDataMessages) {
  const auto [process, tick] = GetParam();
  const FaultRun run = runYard(std::string("kill_") + process, "--kill " + std::string(process) + "@" + std::to_string(tick));
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output << processLog(run);
  const std::string processes = processLog(run);
  EXPECT_NE(processes.find("killing " + std::string(process) + " (SIGKILL) at tick"), std::string::npos) << processes;
  EXPECT_NE(processes.find(std::string(process) + " killed by signal"), std::string::npos);
  EXPECT_NE(processes.find("resuming from the run's log"), std::string::npos);
  // The blackboard is off the lockstep loop: the run may end before it has
  // read the log again, so only the processes the run waits for must say so.
  if (std::string(process) != "blackboard") {
    EXPECT_NE(processes.find("resumed"), std::string::npos);
  }
  expectSameDataMessages(run, cleanRun());
  EXPECT_EQ(run.report["completed"], cleanRun().report["completed"]);
}

// Yard with the siren silenced at t = 10.5 s: the scene changes at tick 105,
// after the keyframe of tick 100, so GT_VERSION names tick 105 until 200.
std::string yardWithASilencedSiren() {
  static const std::string path = [] {
    const std::string dir = makeTempDir("faults_scene_change");
    std::ifstream in(sourceDir() + "/scenarios/yard.xml");
    std::stringstream text;
    text << in.rdbuf();
    std::string yard = text.str();
    const auto end = yard.rfind("</scenario>");
    if (end == std::string::npos) return std::string();
    yard.insert(end, "  <events>\n    <event t=\"10.5\" object=\"siren1\" active=\"0\"/>\n  </events>\n");
    std::ofstream(dir + "/yard_siren_silenced.xml") << yard;
    if (symlink((sourceDir() + "/scenarios/sounds").c_str(), (dir + "/sounds").c_str()) != 0) return std::string();
    return dir + "/yard_siren_silenced.xml";
  }();
  return path;
}

TEST(KilledWorld, AfterASceneChangeItNamesTheSameGroundTruthAndTheRunWritesTheSameDataMessages) {
  const std::string scenario = yardWithASilencedSiren();
  ASSERT_FALSE(scenario.empty());
  const FaultRun clean = runScenario("scene_change_clean", scenario, "");
  ASSERT_EQ(clean.result.exit_code, 0) << clean.result.output;
  // Killed between the change and the next keyframe: the restarted world
  // must know the scene last changed at tick 105, not at the keyframe.
  const FaultRun killed = runScenario("scene_change_killed", scenario, "--kill world@150");
  ASSERT_EQ(killed.result.exit_code, 0) << killed.result.output << processLog(killed);
  EXPECT_NE(processLog(killed).find("world killed by signal"), std::string::npos);
  for (const FaultRun* run : {&clean, &killed}) {
    std::map<int64_t, int64_t> scene_tick;
    for (const auto& v : messagesOn<beft::scene_version_t>(run->log, "GT_VERSION")) scene_tick[v.tick] = v.scene_tick;
    EXPECT_EQ(scene_tick[104], 100);
    EXPECT_EQ(scene_tick[160], 105);
    EXPECT_EQ(scene_tick[200], 200);
    bool silenced = false;
    for (const auto& truth : messagesOn<beft::scene_objects_t>(run->log, "GT_OBJECTS"))
      if (truth.tick == 105)
        for (const auto& o : truth.objects) silenced = silenced || (o.id == "siren1" && !o.sound_active);
    EXPECT_TRUE(silenced) << "no GT_OBJECTS at tick 105 with the siren silent";
  }
  expectSameDataMessages(killed, clean);
}

// Killed after the robot touched what its camera cannot map: the restarted
// vision expert marks the contacts again (from OBSTACLE_MAP_FELT), so the
// robot does not touch the curb again where it already did, and the run
// writes the same data messages.
TEST(KilledVision, AfterContactsMarksThemAgainAndTheRunWritesTheSameDataMessages) {
  const std::string scenario = writeCurbScenario(makeTempDir("curb_scenario"));
  const FaultRun clean = runScenario("curb_clean", scenario, "");
  ASSERT_EQ(clean.result.exit_code, 0) << clean.result.output;
  const auto before_kill = [](const std::vector<Contact>& contacts) {
    int count = 0;
    for (const Contact& contact : contacts) count += contact.tick < 160;
    return count;
  };
  ASSERT_GE(before_kill(contactsWith(processLog(clean), "curb")), 2) << "too few contacts before the kill to test";
  const FaultRun killed = runScenario("curb_killed", scenario, "--kill vision@160");
  ASSERT_EQ(killed.result.exit_code, 0) << killed.result.output << processLog(killed);
  EXPECT_NE(processLog(killed).find("vision killed by signal"), std::string::npos);
  const std::vector<Contact> contacts = contactsWith(processLog(killed), "curb");
  ASSERT_EQ(contacts.size(), contactsWith(processLog(clean), "curb").size());
  for (std::size_t i = 0; i < contacts.size(); ++i)
    for (std::size_t j = i + 1; j < contacts.size(); ++j)
      EXPECT_GT(std::hypot(contacts[i].x - contacts[j].x, contacts[i].y - contacts[j].y), 0.3)
          << "touched the curb twice at one place after the restart";
  expectSameDataMessages(killed, clean);
}

INSTANTIATE_TEST_SUITE_P(EveryKindOfProcess, KilledProcess,
                         ::testing::Values(std::make_pair("fusion", 120), std::make_pair("exploration", 150),
                                           std::make_pair("world", 90), std::make_pair("arbiter", 170),
                                           std::make_pair("planner", 60), std::make_pair("blackboard", 100),
                                           std::make_pair("tasks", 200),
                                           // Between keyframes: it resumes the map's changes since tick 100.
                                           std::make_pair("vision", 150)),
                         [](const auto& info) { return std::string(info.param.first); });

TEST(KilledRecorder, StopsTheRunAndMarksItsLogIncomplete) {
  const FaultRun run = runYard("kill_logger", "--kill logger@100");  // the recorder runs as "logger"
  EXPECT_NE(run.result.exit_code, 0);
  EXPECT_NE(run.result.output.find("the recorder killed by signal"), std::string::npos) << run.result.output;
  EXPECT_NE(run.result.output.find("the run's log is incomplete"), std::string::npos);
  EXPECT_EQ(run.report.value("log_complete", true), false) << run.report.dump();
}

TEST(MalformedTraffic, OnTheRunsOwnChannelsChangesNoDataMessage) {
  const FaultRun& clean = cleanRun();
  ASSERT_EQ(clean.result.exit_code, 0);
  BackgroundRun background = startYard("malformed");
  ASSERT_FALSE(background.url.empty());
  ASSERT_FALSE(background.run_id.empty());
  const pid_t injector = inject(clean.dir + "/run.lcmlog --lcm-url '" + background.url +
                                "' --rate 3000 --damage malformed --into-run " + background.run_id);
  finish(background);
  stop(injector);
  ASSERT_EQ(background.run.result.exit_code, 0) << background.run.result.output;
  expectSameDataMessages(background.run, cleanRun(), LeftOut::kRefused);
  EXPECT_GT(background.run.report["rejected_total"].get<int64_t>(), 1000) << background.run.report.dump();
}

TEST(MalformedTraffic, RandomDamageThatMayDecodeKillsNoProcess) {
  const FaultRun& clean = cleanRun();
  BackgroundRun background = startYard("random_damage");
  ASSERT_FALSE(background.run_id.empty());
  const pid_t injector = inject(clean.dir + "/run.lcmlog --lcm-url '" + background.url +
                                "' --rate 3000 --damage all --seed 3 --into-run " + background.run_id);
  finish(background);
  stop(injector);
  const std::string processes = processLog(background.run);
  EXPECT_EQ(processes.find("killed by signal"), std::string::npos) << processes;
  EXPECT_EQ(processes.find("terminate called"), std::string::npos);
  EXPECT_GT(background.run.report["rejected_total"].get<int64_t>(), 100);
}

TEST(AnotherRun, OnTheSameUrlChangesNoDataMessageAndIsCounted) {
  const FaultRun& clean = cleanRun();
  // Another scenario's recorded run (peek, no run id) and a copy of this
  // one's under another run id, beside this run on its URL.
  BackgroundRun background = startYard("other_run");
  ASSERT_FALSE(background.url.empty());
  const pid_t injector =
      inject(sourceDir() + "/tests/system/data/peek_6_ticks.lcmlog --lcm-url '" + background.url + "' --rate 3000 --as-is");
  const pid_t second = inject(clean.dir + "/run.lcmlog --lcm-url '" + background.url +
                              "' --rate 1000 --as-is --into-run 1234");
  finish(background);
  stop(injector);
  stop(second);
  ASSERT_EQ(background.run.result.exit_code, 0) << background.run.result.output;
  expectSameDataMessages(background.run);
  EXPECT_GT(background.run.report["other_run_messages"].get<int64_t>(), 1000) << background.run.report.dump();
}

// Yesterday's log of the same scenario played on today's URL: lcm-logplayer at
// full speed, over and over, and damaged copies of it at 3000 per second. Its
// run id is yesterday's (every launch draws a fresh one), so all of it is
// another run's: dropped, counted, and nothing of the report is its.
TEST(ReplayedLog, OfAnEarlierRunChangesNoDataMessageAndTheReportIsTheRunsOwn) {
  const FaultRun& clean = cleanRun();
  BackgroundRun background = startYard("replayed_log");
  ASSERT_FALSE(background.url.empty());
  const pid_t player = fork();
  if (player == 0) {
    setpgid(0, 0);  // the loop and its players stop together
    const std::string loop = "while :; do lcm-logplayer --speed=1000000 --lcm-url='" + background.url + "' " +
                             clean.dir + "/run.lcmlog > /dev/null 2>&1; done";
    execl("/bin/sh", "sh", "-c", loop.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const pid_t damaged = inject(clean.dir + "/run.lcmlog --lcm-url '" + background.url +
                               "' --rate 3000 --damage all --seed 11 --as-is");
  finish(background);
  kill(-player, SIGTERM);
  waitpid(player, nullptr, 0);
  stop(damaged);
  ASSERT_EQ(background.run.result.exit_code, 0) << background.run.result.output;
  expectSameDataMessages(background.run);
  EXPECT_EQ(background.run.report["ticks"], clean.report["ticks"]) << background.run.report.dump();
  EXPECT_GT(background.run.report["other_run_messages"].get<int64_t>(), 1000) << background.run.report.dump();
  EXPECT_TRUE(background.run.report.value("log_complete", false)) << background.run.report.dump();
}

TEST(DamagedLog, IsReadToItsEndAndTheDamageReported) {
  const FaultRun& clean = cleanRun();
  ASSERT_EQ(clean.result.exit_code, 0);
  const std::string dir = makeTempDir("damaged_log");
  std::ifstream in(clean.dir + "/run.lcmlog", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  // Garbage in the middle, a record's length field destroyed, and the last event cut.
  bytes.insert(bytes.size() / 3, std::string(5000, '\x5a'));
  bytes[bytes.size() / 2] ^= 0x7f;
  bytes.resize(bytes.size() - 700);
  std::ofstream(dir + "/run.lcmlog", std::ios::binary) << bytes;
  const auto report = runCommand(binDir() + "/beft-report " + dir + "/run.lcmlog --scenario " + sourceDir() +
                                     "/scenarios/yard.xml --out " + dir + " --quiet",
                                 120);
  ASSERT_EQ(report.exit_code, 0) << report.output;
  const auto json = readJson(dir + "/report.json");
  const std::string damage = json["log_damage"];
  EXPECT_NE(damage.find("damaged stretch"), std::string::npos) << damage;
  EXPECT_NE(damage.find("cut short"), std::string::npos) << damage;
  EXPECT_EQ(json["victims"].size(), clean.report["victims"].size());
  EXPECT_NE(report.output.find("warning"), std::string::npos) << report.output;
}

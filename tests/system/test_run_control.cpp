// Pause, step and run on (beft-control, RUN_CONTROL) with real processes: a
// yard run paused early, stepped tick by tick and let go writes exactly the
// data messages of a run that ran through; a paused run ends cleanly on
// SIGINT; a run paced in real time computes what a fast one does.
#include <gtest/gtest.h>

#include <dirent.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <beft/fire_t.hpp>
#include <beft/run_control_t.hpp>
#include <beft/run_status_t.hpp>

#include <chrono>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <thread>

#include "tests/system/run_support.hpp"

using namespace beft::system_test;

namespace {

constexpr int kTicks = 60;
constexpr double kDt_s = 0.1;  // yard's
const std::string kYardArgs = "/scenarios/yard.xml --seed 3 --max-ticks " + std::to_string(kTicks);
// The recorder at the normal priority: what is compared is what it wrote.
const std::string kRecorderInFront = "BEFT_BACKGROUND=0 ";

struct YardRun {
  std::string dir;
  ProgramResult result;
  std::vector<LoggedMessage> log;
};

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

YardRun runYard(const std::string& tag, const std::string& extra_args) {
  YardRun run;
  run.dir = makeTempDir("run_control_" + tag);
  run.result = runCommand(kRecorderInFront + binDir() + "/beft-run " + sourceDir() + kYardArgs + " --out " + run.dir +
                              " " + extra_args,
                          600);
  try {
    run.log = readLog(run.dir + "/run.lcmlog");
  } catch (const std::exception& e) {
    run.result.output += std::string("\n[test] ") + e.what();
  }
  return run;
}

const YardRun& ranThrough() {
  static const YardRun run = runYard("through", "");
  return run;
}

// A run started in the background, and the URL and run id it prints.
struct BackgroundRun {
  pid_t pid = -1;
  YardRun run;
  std::string url, run_id;
};

BackgroundRun startYard(const std::string& tag) {
  BackgroundRun background;
  background.run.dir = makeTempDir("run_control_" + tag);
  const std::string out = background.run.dir + "/run_output.txt";
  background.pid = fork();
  if (background.pid == 0) {
    const std::string command = kRecorderInFront + binDir() + "/beft-run " + sourceDir() + kYardArgs +
                                " --out " + background.run.dir + " > " + out + " 2>&1";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 3000 && (background.url.empty() || background.run_id.empty()); ++i) {  // up to a minute
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const std::string text = fileText(out);
    const std::string line = lineAfter(text, "[run] LCM ");
    if (!line.empty()) background.url = line.substr(0, line.find(';'));
    const std::string started = lineAfter(text, "[launch] started ");
    if (const auto at = started.find(" as run "); at != std::string::npos) background.run_id = started.substr(at + 8);
  }
  return background;
}

void finish(BackgroundRun& background) {
  int status = 0;
  waitpid(background.pid, &status, 0);
  background.run.result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  background.run.result.output = fileText(background.run.dir + "/run_output.txt");
  try {
    background.run.log = readLog(background.run.dir + "/run.lcmlog", nullptr, background.run_id);
  } catch (const std::exception& e) {
    background.run.result.output += std::string("\n[test] ") + e.what();
  }
}

ProgramResult control(const BackgroundRun& background, const std::string& args) {
  return runCommand(binDir() + "/beft-control --lcm-url '" + background.url + "' --run-id " + background.run_id +
                        " --timeout 60 " + args,
                    120);
}

// The tick beft-control says the run holds after; -1 if it does not say so.
int64_t heldAfter(const ProgramResult& said) {
  std::smatch match;
  static const std::regex held("paused after tick ([0-9]+)");
  return std::regex_search(said.output, match, held) ? std::stoll(match[1]) : -1;
}

// A process of this test's run: a descendant of `root` whose program is `name`.
pid_t descendantNamed(pid_t root, const std::string& name) {
  std::map<pid_t, pid_t> parent;
  std::map<pid_t, std::string> program;
  DIR* proc = opendir("/proc");
  if (!proc) return -1;
  while (const dirent* entry = readdir(proc)) {
    const pid_t pid = static_cast<pid_t>(std::atoi(entry->d_name));
    if (pid <= 0) continue;
    const std::string stat = fileText("/proc/" + std::to_string(pid) + "/stat");
    const auto open = stat.find('('), close = stat.rfind(')');
    if (open == std::string::npos || close == std::string::npos) continue;
    program[pid] = stat.substr(open + 1, close - open - 1);
    std::istringstream rest(stat.substr(close + 2));
    char state = 0;
    pid_t ppid = 0;
    rest >> state >> ppid;
    parent[pid] = ppid;
  }
  closedir(proc);
  for (const auto& [pid, comm] : program) {
    if (name.compare(0, comm.size(), comm) != 0) continue;  // comm is cut at 15 characters
    for (pid_t up = parent[pid]; up > 1; up = parent[up])
      if (up == root) return pid;
  }
  return -1;
}

// The ticks of FIREs the arbiter sent while its last RUN_CONTROL_STATE said
// it held after an earlier tick (by the order the recorder took them in).
std::vector<int64_t> firesWhileHeld(const std::vector<LoggedMessage>& log) {
  std::vector<int64_t> ticks;
  std::optional<int64_t> held;
  for (const auto& event : log) {
    if (event.channel == "RUN_CONTROL_STATE") {
      beft::run_control_t state;
      if (state.decode(event.data.data(), 0, static_cast<int>(event.data.size())) <= 0) continue;
      held = state.mode == beft::run_control_t::MODE_PAUSE ? std::optional<int64_t>(state.tick) : std::nullopt;
    } else if (event.channel == "FIRE" && held) {
      beft::fire_t fire;
      if (fire.decode(event.data.data(), 0, static_cast<int>(event.data.size())) > 0 && fire.tick > *held)
        ticks.push_back(fire.tick);
    }
  }
  return ticks;
}

void expectSameDataMessages(const YardRun& run) {
  ASSERT_EQ(ranThrough().result.exit_code, 0) << ranThrough().result.output;
  const DataComparison comparison = compareDataMessages(ranThrough().log, run.log);
  EXPECT_GT(comparison.expected, 200u);
  EXPECT_TRUE(comparison.identical()) << comparison.first_difference;
}

}  // namespace

TEST(RunControl, APausedAndSteppedRunWritesTheDataMessagesOfARunThatRanThrough) {
  BackgroundRun background = startYard("stepped");
  ASSERT_FALSE(background.url.empty() || background.run_id.empty()) << fileText(background.run.dir + "/run_output.txt");
  const ProgramResult paused = control(background, "pause");
  ASSERT_EQ(paused.exit_code, 0) << paused.output;
  const int64_t first = heldAfter(paused);
  ASSERT_GE(first, 0) << paused.output;
  ASSERT_LE(first, kTicks - 10) << "paused too late to step: " << paused.output;
  // Held: asked again, it is where it was.
  EXPECT_EQ(heldAfter(control(background, "status")), first);
  constexpr int kSteps = 4;
  for (int step = 1; step <= kSteps; ++step) {
    const ProgramResult stepped = control(background, "step");
    ASSERT_EQ(stepped.exit_code, 0) << stepped.output;
    EXPECT_EQ(heldAfter(stepped), first + step) << stepped.output;
  }
  EXPECT_EQ(heldAfter(control(background, "status")), first + kSteps);
  const ProgramResult resumed = control(background, "run");
  EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
  finish(background);
  ASSERT_EQ(background.run.result.exit_code, 0) << background.run.result.output;

  // Its log: each hold said in RUN_STATUS and RUN_CONTROL_STATE, and no FIRE of a later tick while held.
  std::map<int64_t, std::string> held_status;
  for (const auto& status : messagesOn<beft::run_status_t>(background.run.log, "RUN_STATUS"))
    if (status.message.find("after tick") != std::string::npos) held_status[status.tick] = status.message;
  EXPECT_NE(held_status[first].find("paused after tick " + std::to_string(first)), std::string::npos);
  for (int step = 1; step <= kSteps; ++step)
    EXPECT_NE(held_status[first + step].find("held after tick " + std::to_string(first + step)), std::string::npos);
  EXPECT_EQ(held_status.size(), static_cast<std::size_t>(kSteps + 1));
  EXPECT_TRUE(firesWhileHeld(background.run.log).empty());
  expectSameDataMessages(background.run);
}

TEST(RunControl, APausedRunEndsCleanlyOnSigint) {
  BackgroundRun background = startYard("sigint");
  ASSERT_FALSE(background.url.empty() || background.run_id.empty()) << fileText(background.run.dir + "/run_output.txt");
  const ProgramResult paused = control(background, "pause");
  ASSERT_EQ(paused.exit_code, 0) << paused.output;
  const int64_t held = heldAfter(paused);
  ASSERT_GE(held, 0) << paused.output;
  const pid_t arbiter = descendantNamed(background.pid, "beft-arbiter");
  ASSERT_GT(arbiter, 0) << "no beft-arbiter under the run";
  ASSERT_EQ(kill(arbiter, SIGINT), 0);
  finish(background);
  EXPECT_EQ(background.run.result.exit_code, 0) << background.run.result.output;
  const std::string processes = fileText(background.run.dir + "/processes.log");
  EXPECT_NE(processes.find("FINISHED: stopped on request after " + std::to_string(held + 1) +
                           " ticks: interrupted (SIGINT)"),
            std::string::npos)
      << processes;
  EXPECT_FALSE(fileText(background.run.dir + "/report.json").empty());
}

TEST(RunControl, ARunPacedInRealTimeComputesWhatAFastRunDoes) {
  const auto start = std::chrono::steady_clock::now();
  const YardRun paced = runYard("real_time", "--real-time");
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(paced.result.exit_code, 0) << paced.result.output;
  // A lower bound only: tick k starts no sooner than k * dt after the first.
  EXPECT_GE(wall_s, (kTicks - 1) * kDt_s);
  EXPECT_NE(fileText(paced.dir + "/processes.log").find("real-time pace"), std::string::npos);
  expectSameDataMessages(paced);
}

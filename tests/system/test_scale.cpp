// Larger scenes with real processes: a generated district run twice at once
// (each loading the machine for the other) writes the same data messages,
// and a robot that drives into what its camera cannot map (a curb below the
// obstacle height) feels it once at each place and goes around.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "tests/system/run_support.hpp"

using namespace beft::system_test;

namespace {

// The recorder at the normal priority: what is compared is what it wrote.
const std::string kRecorderInFront = "BEFT_BACKGROUND=0 ";

struct BackgroundRun {
  std::string dir;
  pid_t pid = -1;
  ProgramResult result;
};

BackgroundRun startRun(const std::string& tag, const std::string& scenario, const std::string& extra) {
  BackgroundRun run;
  run.dir = makeTempDir(tag);
  run.pid = fork();
  if (run.pid == 0) {
    const std::string command = kRecorderInFront + binDir() + "/beft-run " + scenario + " --out " + run.dir + " " +
                                extra + " > " + run.dir + "/run_output.txt 2>&1";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return run;
}

void finish(BackgroundRun& run) {
  int status = 0;
  waitpid(run.pid, &status, 0);
  run.result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.result.output = runCommand("cat " + run.dir + "/run_output.txt", 5).output;
}

std::string processLog(const BackgroundRun& run) { return runCommand("cat " + run.dir + "/processes.log", 10).output; }

int ticksRun(const BackgroundRun& run) {
  const std::string said = lineAfter(processLog(run), "[arbiter] [arbiter] info: FINISHED: finished after ");
  return said.empty() ? -1 : std::stoi(said);
}

}  // namespace

// The generated district, two runs side by side on a 2-core machine: every
// expert waits for its inputs and every plan runs to its own bounds, so the
// machine's load changes no data message (before, a 2 s wall-clock wait for
// inputs and the planners' wall-clock budget made large runs diverge).
TEST(LargeScene, TwoRunsSideBySideWriteTheSameDataMessages) {
  const std::string scenario = sourceDir() + "/scenarios/district_small.xml";
  BackgroundRun first = startRun("scale_a", scenario, "--max-ticks 2000 --no-report");
  BackgroundRun second = startRun("scale_b", scenario, "--max-ticks 2000 --no-report");
  finish(first);
  finish(second);
  ASSERT_EQ(first.result.exit_code, 0) << first.result.output;
  ASSERT_EQ(second.result.exit_code, 0) << second.result.output;
  EXPECT_EQ(ticksRun(first), 2000);
  EXPECT_EQ(ticksRun(second), 2000);
  for (const BackgroundRun* run : {&first, &second}) {
    EXPECT_EQ(processLog(*run).find("firing anyway"), std::string::npos);
  }
  const auto a = readLog(first.dir + "/run.lcmlog");
  const auto b = readLog(second.dir + "/run.lcmlog");
  const DataComparison comparison = compareDataMessages(a, b);
  EXPECT_GT(comparison.expected, 25000u);
  EXPECT_TRUE(comparison.identical()) << comparison.first_difference;
  // Both runs planned: the comparison covers the planner's answers' effects.
  int plan_requests = 0;
  for (const auto& message : a) plan_requests += message.channel == "PLAN_REQUEST";
  EXPECT_GT(plan_requests, 5);
}

// A loaded machine: two busy loops beside a district run, the recorder at
// its usual lower priority. Datagrams it had no room for are asked for again,
// so its log holds every message the processes sent (its final account says
// complete, nothing lost).
TEST(LoadedMachine, TheRecordedLogHoldsEveryMessageSent) {
  std::vector<pid_t> busy;
  for (int i = 0; i < 2; ++i) {
    const pid_t pid = fork();
    if (pid == 0) {
      execl("/bin/sh", "sh", "-c", "while :; do :; done", static_cast<char*>(nullptr));
      _exit(127);
    }
    busy.push_back(pid);
  }
  const std::string dir = makeTempDir("loaded");
  const ProgramResult run = runCommand(binDir() + "/beft-run " + sourceDir() +
                                           "/scenarios/district_small.xml --max-ticks 600 --out " + dir,
                                       900);
  for (pid_t pid : busy) {
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
  }
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto report = readJson(dir + "/report.json");
  EXPECT_TRUE(report.value("log_complete", false)) << report.dump(2);
  EXPECT_EQ(report.value("log_messages_lost", -1), 0) << report.dump(2);
  std::cout << "[loaded machine] the recorder repaired " << report.value("log_messages_repaired", -1)
            << " message(s)\n";
}

// The curb (writeCurbScenario) lies across the way to a calling person, with
// a gap at its north end. The robot drives into it unaware; each contact
// enters the obstacle map, so it never touches the curb twice at one place,
// and it reaches the person round the gap.
TEST(UnseenObstacle, IsFeltOnceAtEachPlaceAndDrivenAround) {
  const std::string dir = makeTempDir("curb");
  const std::string scenario = writeCurbScenario(dir);
  const ProgramResult run = runCommand(kRecorderInFront + binDir() + "/beft-run " + scenario + " --out " + dir, 600);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string processes = runCommand("cat " + dir + "/processes.log", 10).output;
  const std::vector<Contact> contacts = contactsWith(processes, "curb");
  ASSERT_GE(contacts.size(), 1u) << "the robot never touched the curb: the test does not test the bumper";
  for (std::size_t i = 0; i < contacts.size(); ++i)
    for (std::size_t j = i + 1; j < contacts.size(); ++j)
      EXPECT_GT(std::hypot(contacts[i].x - contacts[j].x, contacts[i].y - contacts[j].y), 0.3)
          << "touched the curb twice at one place: (" << contacts[i].x << ", " << contacts[i].y << ")";
  const auto report = readJson(dir + "/report.json");
  EXPECT_EQ(report["completed"], true) << report.dump(2);
  EXPECT_EQ(report["rejected_total"], 0) << report.dump(2);
}

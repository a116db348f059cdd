// An authenticated run (beft run --key): a program without the key plays a
// recorded run's messages onto the keyed run's own channels (a replayed log,
// as beft-inject --as-is does). The keyed run refuses every one of them,
// writes exactly the data messages of an unkeyed run of the same scenario
// and seed, and says how many its processes refused.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "lib/launch/free_port.hpp"
#include "tests/system/run_support.hpp"

using namespace beft::system_test;

namespace {

constexpr int kTicks = 150;

// The recorder at the normal priority: what is compared is what it wrote,
// and the injected traffic loads the machine.
const std::string kRecorderInFront = "BEFT_BACKGROUND=0 ";

struct YardRun {
  std::string dir;
  ProgramResult result;
  std::vector<LoggedMessage> log;
  nlohmann::json report;
};

std::string yardCommand(const std::string& dir, const std::string& extra_args) {
  return kRecorderInFront + binDir() + "/beft-run " + sourceDir() + "/scenarios/yard.xml --max-ticks " +
         std::to_string(kTicks) + " --out " + dir + " " + extra_args;
}

void readResults(YardRun& run, const std::string& run_id) {
  try {
    run.log = readLog(run.dir + "/run.lcmlog", nullptr, run_id);
    run.report = readJson(run.dir + "/report.json");
  } catch (const std::exception& e) {
    run.result.output += std::string("\n[test] ") + e.what();
  }
}

const YardRun& unkeyedRun() {
  static const YardRun run = [] {
    YardRun unkeyed;
    unkeyed.dir = makeTempDir("keyed_reference");
    unkeyed.result = runCommand(yardCommand(unkeyed.dir, ""), 600);
    readResults(unkeyed, "");
    return unkeyed;
  }();
  return run;
}

// A new key in `dir`, made as a user makes one.
std::string newKey(const std::string& dir) {
  const std::string path = dir + "/run.key";
  const ProgramResult made = runCommand(binDir() + "/beft-key new " + path, 30);
  EXPECT_EQ(made.exit_code, 0) << made.output;
  return path;
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A run started in the background, and the URL and run id it prints.
struct BackgroundRun {
  pid_t pid = -1;
  YardRun run;
  std::string url, run_id;
};

BackgroundRun startYard(const std::string& dir, const std::string& extra_args) {
  BackgroundRun background;
  background.run.dir = dir;
  const std::string out = dir + "/run_output.txt";
  background.pid = fork();
  if (background.pid == 0) {
    const std::string command = yardCommand(dir, extra_args) + " > " + out + " 2>&1";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 3000 && (background.url.empty() || background.run_id.empty()); ++i) {  // up to a minute
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const std::string text = readText(out);
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
  background.run.result.output = readText(background.run.dir + "/run_output.txt");
  readResults(background.run, background.run_id);
}

// beft-inject in the background (without the key: its environment has
// none) until stopped.
pid_t injectWithoutTheKey(const std::string& arguments) {
  const pid_t pid = fork();
  if (pid == 0) {
    unsetenv("BEFT_KEY_FILE");
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

TEST(KeyedRun, RefusesAReplayedLogAndWritesTheDataMessagesOfAnUnkeyedRun) {
  const YardRun& unkeyed = unkeyedRun();
  ASSERT_EQ(unkeyed.result.exit_code, 0) << unkeyed.result.output;
  EXPECT_EQ(unkeyed.report.value("unauthenticated_total", -1), 0) << unkeyed.report.dump();

  const std::string dir = makeTempDir("keyed_run");
  const std::string key = newKey(dir);
  BackgroundRun keyed = startYard(dir, "--key " + key);
  ASSERT_FALSE(keyed.url.empty());
  ASSERT_FALSE(keyed.run_id.empty());
  // The unkeyed run's messages, as its log holds them, on the keyed run's channels.
  const pid_t injector = injectWithoutTheKey(unkeyed.dir + "/run.lcmlog --lcm-url '" + keyed.url +
                                             "' --rate 2000 --as-is --into-run " + keyed.run_id);
  finish(keyed);
  stop(injector);
  const std::string processes = readText(dir + "/processes.log");
  ASSERT_EQ(keyed.run.result.exit_code, 0) << keyed.run.result.output << processes;
  EXPECT_NE(keyed.run.result.output.find("the run is keyed"), std::string::npos) << keyed.run.result.output;
  const std::string key_text = readText(key).substr(0, 64);
  EXPECT_EQ(processes.find(key_text), std::string::npos) << "the key was printed";
  EXPECT_EQ(processes.find("killed by signal"), std::string::npos) << processes;

  const DataComparison comparison = compareDataMessages(unkeyed.log, keyed.run.log);
  EXPECT_GT(comparison.expected, 500u);
  EXPECT_TRUE(comparison.identical()) << comparison.first_difference;

  const nlohmann::json& report = keyed.run.report;
  EXPECT_GT(report.value("unauthenticated_total", 0), 0) << report.dump();
  EXPECT_FALSE(report.value("unauthenticated_messages", nlohmann::json::object()).empty()) << report.dump();
  EXPECT_NE(keyed.run.result.output.find("without a valid tag of the run's key"), std::string::npos)
      << keyed.run.result.output;
}

TEST(KeyedRun, AKeyThatCannotBeReadStopsTheRunBeforeAnyProcessStarts) {
  const std::string dir = makeTempDir("keyed_short_key");
  std::ofstream(dir + "/short.key") << "0123456789abcdef\n";
  const ProgramResult run = runCommand(yardCommand(dir, "--key " + dir + "/short.key"), 120);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("at least 32 bytes"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("[launch] started"), std::string::npos) << run.output;
}

// A process given a key file it cannot read ends with the reason rather
// than run open.
TEST(KeyedRun, AProcessWithAnUnreadableKeyFileEndsWithTheReason) {
  const std::string dir = makeTempDir("keyed_missing_key");
  const std::string url = "udpm://239.255.76.67:" + std::to_string(beft::launch::findFreeUdpPort()) + "?ttl=0";
  const ProgramResult task = runCommand("BEFT_KEY_FILE=" + dir + "/no_such.key " + binDir() + "/beft-task --lcm-url '" +
                                            url + "' --run-id 0 push --no-wait goto 1 2 90",
                                        60);
  EXPECT_NE(task.exit_code, 0) << task.output;
  EXPECT_NE(task.output.find("no_such.key"), std::string::npos) << task.output;
  EXPECT_NE(task.output.find("does not run without its key"), std::string::npos) << task.output;
}

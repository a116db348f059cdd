#include "tools/bench_faults/yard_run.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "lib/common/own_bin_dir.hpp"

namespace beft::bench {

pid_t startShell(const std::string& command) {
  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  if (pid > 0) setpgid(pid, pid);  // also here: no race with a stop right after the start
  return pid;
}

void stopShell(pid_t pid) {
  if (pid <= 0) return;
  kill(-pid, SIGTERM);
  waitpid(pid, nullptr, 0);
}

int runShell(const std::string& command, double timeout_s) {
  const pid_t pid = startShell(command);
  if (pid < 0) return -1;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(-pid, SIGTERM);
      std::this_thread::sleep_for(std::chrono::seconds(2));
      kill(-pid, SIGKILL);
      waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

namespace {

// Waits until beft-run has printed its URL and run id (or 5 s passed).
void waitForUrlAndRun(const std::string& out_path, std::string& url, std::string& run_id) {
  for (int i = 0; i < 500 && (url.empty() || run_id.empty()); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const std::string out = readFile(out_path);
    url = lineAfter(out, "[run] LCM ");
    url = url.substr(0, url.find(';'));
    const std::string started = lineAfter(out, "[launch] started ");
    if (const auto at = started.find(" as run "); at != std::string::npos) run_id = started.substr(at + 8);
  }
}

}  // namespace

Outcome runYard(const std::string& name, const std::string& dir, const std::string& args, int ticks,
                const During& during) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const pid_t runner = startShell(ownBinDir() + "/beft-run " + BEFT_SOURCE_DIR + "/scenarios/yard.xml --max-ticks " +
                                  std::to_string(ticks) + " --out " + dir + " " + args + " > " + dir +
                                  "/out.txt 2>&1");
  pid_t helper = -1;
  if (during) {
    std::string url, run_id;
    waitForUrlAndRun(dir + "/out.txt", url, run_id);
    helper = during(url, run_id);
  }
  waitpid(runner, nullptr, 0);
  stopShell(helper);
  Outcome outcome;
  outcome.name = name;
  const std::string out = readFile(dir + "/out.txt");
  outcome.run_id = runIdIn(out);
  readRun(dir + "/report.json", readFile(dir + "/processes.log"), outcome);
  return outcome;
}

}  // namespace beft::bench

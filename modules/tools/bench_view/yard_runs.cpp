#include "tools/bench_view/yard_runs.hpp"

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <thread>

#include "lib/common/clocks.hpp"
#include "lib/common/own_bin_dir.hpp"
#include "tools/bench_view/bridge_usage.hpp"
#include "tools/bench_view/child_process.hpp"

namespace beft::bench {

namespace {

constexpr double kConnectTimeout_s = 180;
// After the page is connected and read: its first frames (parsing, building
// the scene) are not what watching a run costs.
constexpr double kSettle_s = 2;

void sleepMs(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

std::string runCommand(const YardRunRequest& r) {
  std::string command = "exec " + ownBinDir() + "/beft-run " + shellQuoted(r.source_dir + "/scenarios/yard.xml") +
                        " --fast --max-ticks " + std::to_string(r.ticks) + " --seed " + std::to_string(r.seed) +
                        " --out " + shellQuoted(r.dir);
  if (r.view_port > 0) command += " --view --port " + std::to_string(r.view_port);
  return command + " > " + shellQuoted(r.dir + "/out.txt") + " 2>&1";
}

// beft-control on the run's URL: "pause" or "run"; true when it worked.
bool control(const std::string& dir, const std::string& action) {
  const std::string out = readFile(dir + "/out.txt");
  std::string url = lineAfter(out, "[run] LCM ");
  url = url.substr(0, url.find(';'));
  const std::string started = lineAfter(out, "[launch] started ");
  const auto at = started.find(" as run ");
  if (url.empty() || at == std::string::npos) return false;
  const std::string command = ownBinDir() + "/beft-control --lcm-url " + shellQuoted(url) + " --run-id " +
                              started.substr(at + 8) + " --origin bench --timeout 60 " + action + " >> " +
                              shellQuoted(dir + "/control.txt") + " 2>&1";
  return runShell(command) == 0;
}

// Whether the page, connected to the held run, has been read once (it has
// taken in what the bridge gives a new page: the latest of each channel) and
// then had kSettle_s more.
bool pageSettled(const PageProbe& probe, std::chrono::steady_clock::time_point& read_at) {
  const auto now = std::chrono::steady_clock::now();
  if (read_at == std::chrono::steady_clock::time_point{}) {
    if (probe.readings().samples.empty()) return false;
    read_at = now;
  }
  return now - read_at > std::chrono::duration<double>(kSettle_s);
}

// Waits for the run's launch line, pauses it, holds it for at least
// `hold_s` and, with a page, until the page is connected and settled, and
// lets it run on; "" or what went wrong. The wall time it was let go is in
// `resumed_us`.
std::string hold(const std::string& dir, pid_t runner, const PageProbe* probe, double hold_s, int64_t& resumed_us) {
  for (int i = 0; i < 6000 && lineAfter(readFile(dir + "/out.txt"), "[launch] started ").empty(); ++i) {
    if (hasEnded(runner)) return "the run ended before it started its processes";
    sleepMs(10);
  }
  if (!control(dir, "pause")) return "beft-control could not pause the run (see control.txt)";
  const auto paused = std::chrono::steady_clock::now();
  const auto deadline = paused + std::chrono::duration<double>(kConnectTimeout_s);
  std::chrono::steady_clock::time_point read_at{};
  while ((probe && !pageSettled(*probe, read_at)) ||
         std::chrono::steady_clock::now() - paused < std::chrono::duration<double>(hold_s)) {
    if (probe && probe->ended()) return "the page probe ended: " + readFile(dir + "/probe.txt");
    if (std::chrono::steady_clock::now() > deadline) return "the page was not connected and read within 180 s";
    sleepMs(50);
  }
  resumed_us = wallMicros();
  return control(dir, "run") ? "" : "beft-control could not let the run go on (see control.txt)";
}

// Waits for the run's end, reading the bridge's use meanwhile; the exit code.
int waitForRun(pid_t runner, int view_port, YardRun& run) {
  int status = 0;
  while (waitpid(runner, &status, WNOHANG) == 0) {
    if (view_port > 0) {  // only then: reading /proc costs the run a little CPU
      const auto usage = bridgeUsage(view_port);
      if (usage.rss_kb > 0) run.bridge_rss_kb = usage.rss_kb, run.bridge_cpu_s = usage.cpu_s;
    }
    sleepMs(100);
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

YardRun runYard(const YardRunRequest& request) {
  std::filesystem::remove_all(request.dir);
  std::filesystem::create_directories(request.dir);
  YardRun run;
  std::unique_ptr<PageProbe> probe;
  if (request.view_port > 0)  // the browser first: it is up when the viewer begins to serve
    probe = std::make_unique<PageProbe>("http://127.0.0.1:" + std::to_string(request.view_port) + "/", 1000, 0,
                                        request.dir + "/probe.txt");
  const pid_t runner = startShell(runCommand(request));
  const auto held = std::chrono::steady_clock::now();
  int64_t resumed_us = -1;
  run.problem = hold(request.dir, runner, probe.get(), request.hold_s, resumed_us);
  run.held_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - held).count();
  if (!run.problem.empty()) stopGroup(runner, SIGINT, 30);
  const int code = waitForRun(runner, request.view_port, run);
  run.completed = code == 0 && run.problem.empty();
  if (probe) {
    probe->stop();
    run.page = probe->readings();
  }
  if (run.problem.empty() && code != 0) run.problem = "beft-run exited with " + std::to_string(code);
  run.times = readTickTimes(request.dir + "/run.lcmlog");
  if (resumed_us >= 0 && run.problem.empty()) run.resumed_at_tick = run.times.firstTickFiredAfter(resumed_us);
  return run;
}

}  // namespace beft::bench

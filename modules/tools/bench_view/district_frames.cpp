#include "tools/bench_view/district_frames.hpp"

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <thread>
#include <vector>

#include "lib/common/own_bin_dir.hpp"
#include "tools/bench_view/bridge_usage.hpp"
#include "tools/bench_view/child_process.hpp"
#include "tools/bench_view/tick_times.hpp"

namespace beft::bench {

namespace {

constexpr int kReadEveryMs = 2000;
constexpr double kStartAllowance_s = 300;  // to start the run's processes and the page

void summarise(DistrictFrames& result) {
  const auto& samples = result.page.samples;
  if (samples.size() < 2) {
    result.problem = "the page was read fewer than twice";
    return;
  }
  std::vector<double> frame_ms;
  for (const auto& s : samples) frame_ms.push_back(s.frame_time_ms);
  std::nth_element(frame_ms.begin(), frame_ms.begin() + frame_ms.size() / 2, frame_ms.end());
  result.median_frame_ms = frame_ms[frame_ms.size() / 2];
  const auto& first = samples.front();
  const auto& last = samples.back();
  const double span_s = (last.wall_ms - first.wall_ms) * 1e-3;
  if (span_s <= 0) return;
  result.frames_per_s = (last.frames - first.frames) / span_s;
  result.renders_per_s = (last.renders - first.renders) / span_s;
  result.page_ticks_per_s = (last.tick - first.tick) / span_s;
}

}  // namespace

DistrictFrames measureDistrictFrames(const DistrictRequest& r) {
  std::filesystem::remove_all(r.dir);
  std::filesystem::create_directories(r.dir);
  DistrictFrames result;
  PageProbe probe("http://127.0.0.1:" + std::to_string(r.view_port) + "/", kReadEveryMs, r.seconds,
                  r.dir + "/probe.txt");
  const long long ticks = static_cast<long long>((r.seconds + kStartAllowance_s) * 10);  // dt 0.1 s
  const pid_t runner = startShell("exec " + ownBinDir() + "/beft-run " +
                                  shellQuoted(r.source_dir + "/scenarios/district_large.xml") + " --max-ticks " +
                                  std::to_string(ticks) + " --view --port " + std::to_string(r.view_port) +
                                  " --no-report --out " + shellQuoted(r.dir) + " > " + shellQuoted(r.dir + "/out.txt") +
                                  " 2>&1");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(r.seconds + kStartAllowance_s);
  while (!probe.ended() && !hasEnded(runner) && std::chrono::steady_clock::now() < deadline) {
    if (const auto usage = bridgeUsage(r.view_port); usage.rss_kb > 0) result.bridge_rss_kb = usage.rss_kb;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  probe.stop();
  stopGroup(runner, SIGINT, 60);
  result.page = probe.readings();
  if (!result.page.unavailable.empty()) result.problem = result.page.unavailable;
  else if (result.page.connected_ms < 0) result.problem = "the page did not connect (see " + r.dir + "/probe.txt)";
  else summarise(result);
  const TickTimes times = readTickTimes(r.dir + "/run.lcmlog");
  if (result.page.connected_ms >= 0)
    result.run_ticks_per_s = times.ticksPerSecondFrom(times.firstTickFiredAfter(result.page.connected_ms * 1000));
  if (!result.page.samples.empty()) {
    const auto& last = result.page.samples.back();
    result.page_behind_ticks = times.tickAt(last.wall_ms * 1000) - last.tick;
  }
  return result;
}

}  // namespace beft::bench

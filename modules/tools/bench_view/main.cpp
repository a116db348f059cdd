// beft-bench-view: what watching a run costs. yard.xml at full speed
// (--fast) without a viewer and with the bridge running and the page open
// in headless Chromium, in turns: the lockstep loop's ticks per second and
// the ratio (target: the viewed loop keeps >= 90 % of its speed); then the
// page's frame time on district_large at the real-time pace; the bridge's
// resident memory at the end of each viewed run.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "lib/common/command_line.hpp"
#include "tools/bench_view/district_frames.hpp"
#include "tools/bench_view/page_probe.hpp"
#include "tools/bench_view/speed_rows.hpp"

namespace {

using beft::bench::ViewOptions;

std::optional<int> parseOptions(int argc, char** argv, ViewOptions& o) {
  CLI::App app("Runs yard.xml at full speed (--fast, fixed seed) without a viewer and with beft-bridge running and "
               "its page open in headless Chromium (Debian's chromium, WebGL by SwiftShader), in turns, and prints "
               "each run's lockstep ticks per second (from its log: the ticks after a hold at the start, alike for "
               "both kinds, a viewed run held until its page has connected and settled), the means and viewed / "
               "plain (target >= 0.90, a verdict, not a failure); then district_large with the viewer at the real-time pace for --seconds: the "
               "page's median frame time (its rolling mean of the intervals between the frames it drew, read "
               "every 2 s) and frames per second, how far it is behind the run; and beft-bridge's VmRSS (and CPU "
               "time) at the end of each viewed run. Without node, chromium or puppeteer-core it says so and "
               "prints the runs without a viewer.",
               "beft-bench-view");
  app.add_option("--ticks", o.ticks, "ticks per yard run")->capture_default_str()->check(CLI::Range(50, 100000));
  app.add_option("--repeat", o.repeat, "yard runs of each kind")->capture_default_str()->check(CLI::Range(1, 20));
  app.add_option("--seed", o.seed, "the yard runs' seed")->capture_default_str();
  app.add_option("--hold", o.hold_s,
                 "seconds every yard run is held at its start (a viewed one also until its page has settled)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 120.0));
  app.add_option("--seconds", o.seconds, "wall time of the page read on district_large (0: skip it)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 3600.0));
  app.add_option("--work", o.work, "folder for the runs")->capture_default_str();
  return beft::parseCommandLine(app, argc, argv);
}

void printDistrict(const beft::bench::DistrictFrames& d, double seconds) {
  std::printf("\ndistrict_large, real-time pace, page read every 2 s for %.0f s:\n", seconds);
  if (!d.problem.empty()) {
    std::printf("  not measured: %s\n", d.problem.c_str());
    return;
  }
  std::printf("  median frame time %.1f ms (%.1f frames/s by it); counted: %.1f frames/s, %.1f renders/s of the "
              "3-D view; %zu readings, %zu page errors\n",
              d.median_frame_ms, d.median_frame_ms > 0 ? 1000.0 / d.median_frame_ms : 0.0, d.frames_per_s,
              d.renders_per_s, d.page.samples.size(), d.page.page_errors.size());
  std::printf("  ticks/s: %.1f shown by the page, %.1f run (its log; real time is 10); at the last reading the "
              "page showed %lld ticks behind the run\n",
              d.page_ticks_per_s, d.run_ticks_per_s, d.page_behind_ticks);
  if (d.bridge_rss_kb > 0) std::printf("  beft-bridge VmRSS at the end: %.1f MB\n", d.bridge_rss_kb / 1024.0);
}

}  // namespace

int main(int argc, char** argv) {
  ViewOptions o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  std::filesystem::create_directories(o.work);
  const std::string unavailable = beft::bench::probeUnavailable(o.work);
  if (!unavailable.empty())
    std::printf("viewer not measured: %s\nyard without a viewer only:\n\n", unavailable.c_str());
  beft::bench::runSpeedRows(o, unavailable.empty());
  if (unavailable.empty() && o.seconds > 0)
    printDistrict(beft::bench::measureDistrictFrames({BEFT_SOURCE_DIR, o.work + "/district_large", o.seconds,
                                                      beft::bench::freeTcpPort()}),
                  o.seconds);
  std::printf("runs in %s\n", o.work.c_str());
  return 0;
}

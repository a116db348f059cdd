// beft-bench-scale (./beft bench scale): how the cost of a tick and the size
// of the log grow with the scene. Runs the mission on yard (30 x 20 m, 14
// objects) and the generated districts (80 x 60 m, 114 objects; 160 x 120 m,
// 450 objects), alternately when repeated, and prints each one's lockstep
// ticks per second, times real time, milliseconds per tick relative to
// yard's in the same invocation, and MB of log per simulated minute, beside
// the targets.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "lib/common/command_line.hpp"
#include "lib/common/own_bin_dir.hpp"
#include "lib/common/quiet_child.hpp"

namespace {

namespace fs = std::filesystem;

struct Scene {
  std::string name;
  long max_ticks;            // -1: the whole mission
  double target_real_time;   // lockstep loop, times real time
  double target_mb_per_min;  // log size per simulated minute
};

struct Figures {
  bool ok = false;
  long ticks = 0;
  double ticks_per_s = 0, real_time = 0, mb_per_min = 0;
  int collisions = 0;
};

// Runs beft-run to completion, quietly; its report and log give the figures.
Figures runScene(const Scene& scene, const std::string& out_dir, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {beft::ownBinDir() + "/beft-run",
                                   std::string(BEFT_SOURCE_DIR) + "/scenarios/" + scene.name + ".xml", "--out", out_dir};
  if (scene.max_ticks > 0) args.insert(args.end(), {"--max-ticks", std::to_string(scene.max_ticks)});
  args.insert(args.end(), extra.begin(), extra.end());
  const int exit_code = beft::runQuietly(args);
  Figures figures;
  if (exit_code != 0) return figures;
  try {
    std::ifstream in(out_dir + "/report.json");
    const nlohmann::json report = nlohmann::json::parse(in);
    figures.ticks = report.at("ticks").get<long>();
    figures.ticks_per_s = report.at("ticks_per_s").get<double>();
    figures.real_time = report.at("realtime_factor").get<double>();
    figures.collisions = report.at("collisions").get<int>();
    const double minutes = report.at("sim_time_s").get<double>() / 60.0;
    const double bytes = static_cast<double>(fs::file_size(out_dir + "/run.lcmlog"));
    figures.mb_per_min = minutes > 0 ? bytes / 1e6 / minutes : 0;
    figures.ok = figures.ticks > 0 && figures.ticks_per_s > 0;
  } catch (const std::exception&) {
    figures.ok = false;
  }
  return figures;
}

struct Options {
  long district_ticks = 1500;
  int repeats = 3;  // the host is shared: a median of three alternated runs moves less than one run
  std::vector<std::string> extra;
  bool keep = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Runs the mission on yard (whole) and on the generated districts district_small and district_large (the "
      "first --district-ticks ticks each), alternately --repeats times, and prints per scene: lockstep ticks per "
      "second, times real time, milliseconds per tick relative to yard's in this invocation, MB of log per "
      "simulated minute and collisions, beside the targets (district_large >= 25x real time, yard >= 50x; yard "
      "<= 15 MB and district_large <= 50 MB per simulated minute). Exits 1 if a run fails, not on a missed target.",
      "beft-bench-scale");
  app.add_option("--district-ticks", o.district_ticks, "ticks of each district run")
      ->check(CLI::Range(100L, 1000000L))->capture_default_str();
  app.add_option("--repeats", o.repeats, "runs of each scene (alternated; the medians are printed)")
      ->check(CLI::Range(1, 20))->capture_default_str();
  app.add_option("--run-arg", o.extra, "another argument for every beft-run (repeatable), e.g. --run-arg=--record-camera=none");
  app.add_flag("--keep", o.keep, "keep the run folders (printed)");
  return beft::parseCommandLine(app, argc, argv);
}

// The figures of every run of each scene, the scenes run alternately
// --repeats times in folders under `root`; nothing if a run failed (said on
// stderr).
std::optional<std::vector<std::vector<Figures>>> runAlternately(const std::vector<Scene>& scenes, const Options& o,
                                                                const fs::path& root) {
  std::vector<std::vector<Figures>> runs(scenes.size());
  for (int r = 0; r < o.repeats; ++r) {
    for (std::size_t s = 0; s < scenes.size(); ++s) {
      const std::string dir = (root / (scenes[s].name + "_" + std::to_string(r))).string();
      std::fprintf(stderr, "[bench] %s, run %d of %d ...\n", scenes[s].name.c_str(), r + 1, o.repeats);
      const Figures figures = runScene(scenes[s], dir, o.extra);
      if (!figures.ok) {
        std::fprintf(stderr, "[bench] error: the run of %s failed (see %s/processes.log)\n", scenes[s].name.c_str(),
                     dir.c_str());
        return std::nullopt;
      }
      runs[s].push_back(figures);
      if (!o.keep) fs::remove(fs::path(dir) / "run.lcmlog");
    }
  }
  return runs;
}

// The median of one figure over a scene's runs.
double medianOf(const std::vector<Figures>& runs, double Figures::*field) {
  std::vector<double> values;
  for (const Figures& f : runs) values.push_back(f.*field);
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

void printFigures(const std::vector<Scene>& scenes, const std::vector<std::vector<Figures>>& runs) {
  const double yard_ms = 1000.0 / medianOf(runs[0], &Figures::ticks_per_s);
  std::printf("%-16s %7s %9s %9s %9s %12s %11s %10s\n", "scene", "ticks", "ticks/s", "x real", "ms/tick",
              "vs yard", "MB/sim min", "collisions");
  for (std::size_t s = 0; s < scenes.size(); ++s) {
    const double ticks_per_s = medianOf(runs[s], &Figures::ticks_per_s);
    const double real_time = medianOf(runs[s], &Figures::real_time);
    const double mb = medianOf(runs[s], &Figures::mb_per_min);
    const double ms = 1000.0 / ticks_per_s;
    std::printf("%-16s %7ld %9.1f %9.1f %9.2f %11.2fx %11.1f %10d\n", scenes[s].name.c_str(), runs[s][0].ticks,
                ticks_per_s, real_time, ms, ms / yard_ms, mb, runs[s][0].collisions);
  }
}

void printTargets(const std::vector<Scene>& scenes, const std::vector<std::vector<Figures>>& runs) {
  std::printf("\ntargets:");
  for (std::size_t s = 0; s < scenes.size(); ++s) {
    if (scenes[s].target_real_time <= 0) continue;
    const double real_time = medianOf(runs[s], &Figures::real_time), mb = medianOf(runs[s], &Figures::mb_per_min);
    std::printf(" %s %.0fx real time (target >= %.0fx: %s), %.1f MB/min (target <= %.0f: %s);", scenes[s].name.c_str(),
                real_time, scenes[s].target_real_time, real_time >= scenes[s].target_real_time ? "met" : "missed", mb,
                scenes[s].target_mb_per_min, mb <= scenes[s].target_mb_per_min ? "met" : "missed");
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  const std::vector<Scene> scenes = {{"yard", -1, 50, 15},
                                     {"district_small", o.district_ticks, 0, 0},
                                     {"district_large", o.district_ticks, 25, 50}};
  const fs::path root = fs::temp_directory_path() / ("beft_bench_scale_" + std::to_string(getpid()));
  const auto runs = runAlternately(scenes, o, root);
  if (!runs) return 1;
  printFigures(scenes, *runs);
  printTargets(scenes, *runs);
  if (o.keep) std::printf("run folders: %s\n", root.c_str());
  else fs::remove_all(root);
  return 0;
}

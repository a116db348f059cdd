#include "tools/experiment/experiment_runner.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "lib/common/own_bin_dir.hpp"
#include "tools/experiment/episodes.hpp"
#include "tools/experiment/experiment_file.hpp"
#include "tools/experiment/local_pool.hpp"
#include "tools/experiment/plots.hpp"
#include "tools/experiment/scenes.hpp"
#include "tools/experiment/slurm_runner.hpp"
#include "tools/experiment/summary_output.hpp"

namespace beft::experiment {
namespace {

namespace fs = std::filesystem;

void say(const std::string& line) {
  std::printf("[experiment] %s\n", line.c_str());
  std::fflush(stdout);
}

PoolJob jobOf(const Experiment& x, const Episode& episode, const RunnerOptions& o) {
  const std::string folder = episodeFolder(o.out_dir, episode);
  PoolJob job{episode.id, folder, runCommand(x, episode, folder, ownBinDir()), {}, o.keep_logs};
  job.recorded = recordedCommand(job.command, o.out_dir);
  return job;
}

// What the episode's folder holds, missing if it was run with other options
// (a changed max_ticks, scene file, ...): its results are not this experiment's.
EpisodeState stateOf(const PoolJob& job, bool say_stale) {
  EpisodeState state = readEpisodeState(job.folder);
  if (state.status == Status::missing || state.command == job.recorded) return state;
  if (say_stale) say(job.id + " was run with other options (its episode.json): it runs again");
  return {};
}

// The episodes to run now: those missing, and the failed ones with --retry-failed.
std::vector<PoolJob> jobsToRun(const Experiment& x, const std::vector<Episode>& episodes, const RunnerOptions& o) {
  std::vector<PoolJob> jobs;
  int done = 0, failed = 0;
  for (const auto& episode : episodes) {
    const PoolJob job = jobOf(x, episode, o);
    const Status status = stateOf(job, true).status;
    done += status == Status::done;
    failed += status == Status::failed;
    if (status == Status::missing || (status == Status::failed && o.retry_failed)) jobs.push_back(job);
  }
  say(x.name + ": " + std::to_string(episodes.size()) + " episodes in " + o.out_dir + ": " + std::to_string(done) + " done, " +
      std::to_string(failed) + " failed" + (failed > 0 && !o.retry_failed ? " (not run again without --retry-failed)" : "") +
      ", " + std::to_string(jobs.size()) + " to run " +
      (o.slurm ? "on Slurm" : "with " + std::to_string(o.jobs) + " job(s)"));
  return jobs;
}

std::vector<EpisodeResult> collect(const Experiment& x, const std::vector<Episode>& episodes,
                                   const RunnerOptions& o) {
  std::vector<EpisodeResult> results;
  for (const auto& episode : episodes) {
    const PoolJob job = jobOf(x, episode, o);
    EpisodeResult r{episode, stateOf(job, false), std::nullopt};
    if (r.state.status == Status::done) r.metrics = readMetrics((fs::path(job.folder) / "report.json").string());
    results.push_back(r);
  }
  return results;
}

void writeResults(const Experiment& x, const std::vector<EpisodeResult>& results, const std::string& out_dir) {
  const Summary summary = summarise(x, results);
  std::ofstream episodes_csv(fs::path(out_dir) / "episodes.csv");
  writeEpisodesCsv(x, results, episodes_csv);
  std::ofstream summary_csv(fs::path(out_dir) / "summary.csv");
  writeSummaryCsv(summary, summary_csv);
  nlohmann::json json = summaryJson(summary);
  json["experiment"] = x.name;
  json["episodes"] = results.size();
  std::ofstream(fs::path(out_dir) / "summary.json") << json.dump(2) << "\n";
  if (!writeSuccessPlot(summary, (fs::path(out_dir) / "success.png").string()) ||
      !writeTimeToFindPlot(results, (fs::path(out_dir) / "time_to_find.png").string()))
    say("warning: cannot write the pictures in " + out_dir);
  std::cout << "\n";
  printSummary(summary, std::cout);
  std::cout << "\n";
  int logs_removed = 0;
  for (const auto& r : results) {
    if (r.state.status == Status::failed) say("failed: " + r.episode.id + ": " + r.state.reason);
    logs_removed += r.state.log_removed;
  }
  if (logs_removed > 0)
    say("run logs: removed for " + std::to_string(logs_removed) +
        " episode(s) that succeeded (--keep-logs all keeps them; each episode.json has the command that makes it again)");
  say("wrote " + out_dir + "/episodes.csv, summary.csv, summary.json, success.png, time_to_find.png");
}

// Episodes per hour, and the pool's speed-up over one job: simulated
// seconds per wall second of the episodes run side by side, over those of
// the first episode run alone in this same invocation (local_pool.hpp).
void sayPace(const PoolOutcome& pool, int jobs) {
  if (pool.done == 0 || pool.wall_s <= 0) return;
  char line[512];
  const std::string where = jobs > 0 ? "with " + std::to_string(jobs) + " job(s)" : "on Slurm";
  std::snprintf(line, sizeof(line), "%d episode(s) done in %.1f s: %.0f episodes per hour %s", pool.done, pool.wall_s,
                pool.done * 3600 / pool.wall_s, where.c_str());
  say(line);
  if (!pool.hasSpeedUp()) return;
  std::snprintf(line, sizeof(line),
                "speed-up of %d jobs over one: %.2fx (one job, %s alone: %.1f simulated s per wall s; %d jobs, the "
                "other %d episode(s): %.1f)",
                jobs, pool.pooled.rate() / pool.alone.rate(), pool.alone_id.c_str(), pool.alone.rate(), jobs,
                pool.pooled.episodes, pool.pooled.rate());
  say(line);
}

int exitCode(const PoolOutcome& pool, const std::vector<EpisodeResult>& results) {
  if (pool.interrupted) return 130;
  for (const auto& r : results)
    if (r.state.status != Status::done) return 1;
  return 0;
}

// --run-episode ID: that episode, run as the local pool runs each one (what a Slurm task does).
int runOneEpisode(const Experiment& x, const std::vector<Episode>& episodes, const RunnerOptions& o) {
  for (const auto& episode : episodes)
    if (episode.id == o.run_episode) {
      const PoolOutcome pool = runLocalPool({jobOf(x, episode, o)}, 1, say);
      return pool.interrupted ? 130 : pool.done == 1 ? 0 : 1;
    }
  std::fprintf(stderr, "[experiment] error: %s has no episode '%s' (--list prints them)\n", o.file.c_str(),
               o.run_episode.c_str());
  return 2;
}

SlurmRun slurmRun(const Experiment& x, const RunnerOptions& o) {
  const std::string file = fs::absolute(o.file).lexically_normal().string();
  return {o.limits, o.slurm_wait, x.name, o.out_dir,
          {ownBinDir() + "/beft-experiment", file, "--out", o.out_dir, "--keep-logs", nameOf(o.keep_logs), "--run-episode"}};
}

// The missing episodes run, locally or on Slurm; the exit code when there is
// nothing to gather (a Slurm job not waited for, or not submitted).
std::optional<int> runJobs(const Experiment& x, const std::vector<Episode>& episodes, const RunnerOptions& o,
                           PoolOutcome& pool) {
  const auto jobs = jobsToRun(x, episodes, o);
  if (!o.slurm) {
    pool = runLocalPool(jobs, o.jobs, say);
    return std::nullopt;
  }
  const SlurmOutcome slurm = runOnSlurm(jobs, slurmRun(x, o), say);
  pool = slurm.pool;
  return slurm.gather ? std::nullopt : std::optional<int>(slurm.exit_code);
}

}  // namespace

int runExperiment(const RunnerOptions& options) {
  Experiment x;
  std::vector<Episode> episodes;
  try {
    x = readExperiment(options.file);
    episodes = expandEpisodes(x);
  } catch (const ExperimentError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  if (options.list_only) {
    for (const auto& e : episodes) std::printf("%s\n", e.id.c_str());
    return 0;
  }
  if (options.slurm && !haveSlurmCommands()) return 2;
  try {
    fs::create_directories(options.out_dir);
    generateScenes(x, options.out_dir, ownBinDir(), say);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "[experiment] error: %s\n", e.what());
    return 1;
  }
  if (!options.run_episode.empty()) return runOneEpisode(x, episodes, options);
  PoolOutcome pool;
  if (const auto code = runJobs(x, episodes, options, pool)) return *code;
  const auto results = collect(x, episodes, options);
  writeResults(x, results, options.out_dir);
  sayPace(pool, options.slurm ? 0 : options.jobs);
  if (pool.interrupted) say("interrupted: start it again to run what is missing");
  return exitCode(pool, results);
}

}  // namespace beft::experiment

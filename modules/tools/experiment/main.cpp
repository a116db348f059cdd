// beft-experiment: many episodes of the mission over scenes and factors, with
// the statistics of their outcome (./beft experiment FILE).
#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>

#include "lib/common/command_line.hpp"
#include "tools/experiment/experiment_runner.hpp"
#include "tools/experiment/local_pool.hpp"

namespace {

// --slurm and its limits; --run-episode, hidden, is what each of the job's tasks runs.
void addSlurmOptions(CLI::App& app, beft::experiment::RunnerOptions& o) {
  auto* slurm = app.add_flag("--slurm", o.slurm,
                             "run the missing episodes on Slurm: an sbatch array job, one task per episode, writing "
                             "into OUT (on a file system the nodes share); started again, it gathers the rows");
  app.add_option("--partition", o.limits.partition, "the job's partition (default: the cluster's)")->needs(slurm);
  app.add_option("--time-limit", o.limits.time_limit_min, "each task's time limit in minutes")
      ->check(CLI::PositiveNumber)
      ->needs(slurm);
  app.add_option("--mem", o.limits.mem_mb, "each task's memory in MB")->check(CLI::PositiveNumber)->needs(slurm);
  app.add_option("--cpus-per-task", o.limits.cpus_per_task, "each task's CPUs")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->needs(slurm);
  app.add_flag("--slurm-wait", o.slurm_wait, "wait for the job's end, then gather its rows and write the summary")
      ->needs(slurm);
  app.add_option("--run-episode", o.run_episode, "run this one episode (what a task of the Slurm job runs)")
      ->group("")
      ->excludes(slurm);
}

std::optional<int> parseOptions(int argc, char** argv, beft::experiment::RunnerOptions& o) {
  CLI::App app(
      "Runs an experiment: the episodes of an experiment file (the product of its scenes, generated ones "
      "included, seeds, planners, acoustics, nets and --set parameters), each an ordinary beft-run in "
      "OUT/episodes/ID/, at most --jobs at once. Resumable: an episode already done is not run again, one that "
      "failed is reported with its reason and run again only with --retry-failed, one run with other options "
      "(the file changed) runs again; interrupted (Ctrl-C), it runs what is missing when started again. Writes "
      "OUT/episodes.csv (one row per episode), OUT/summary.csv and OUT/summary.json (per condition: success "
      "rate with its 95 % Wilson interval, quartiles of time to find, "
      "collisions; paired comparisons: McNemar's exact test on success, Wilcoxon's signed-rank test on time to "
      "find), OUT/success.png and OUT/time_to_find.png, and prints the summary, the episodes per hour and, with "
      "more than one job, the pool's speed-up over one job (its first episode runs alone). The file's format: "
      "modules/tools/README.md. With --slurm, the episodes run as an sbatch array job.",
      "beft-experiment");
  app.add_option("file", o.file, "experiment XML file")->required()->check(CLI::ExistingFile);
  app.add_option("--out", o.out_dir, "the experiment's folder (default logs/experiment-<file name>/)");
  app.add_option("--jobs,-j", o.jobs, "episodes run at once (default: half the cores, at least 1)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_flag("--retry-failed", o.retry_failed, "run the episodes that failed again");
  app.add_flag("--list", o.list_only, "print the episodes' ids and run nothing");
  std::string keep_logs = beft::experiment::nameOf(o.keep_logs);
  app.add_option("--keep-logs", keep_logs,
                 "which episodes keep their run.lcmlog: unsuccessful (failed, not completed or with a collision: "
                 "a successful episode's command, in its episode.json, makes the same messages again) or all")
      ->capture_default_str()
      ->check(CLI::IsMember({beft::experiment::nameOf(beft::experiment::KeepLogs::unsuccessful),
                             beft::experiment::nameOf(beft::experiment::KeepLogs::all)}));
  addSlurmOptions(app, o);
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  o.keep_logs = *beft::experiment::keepLogsNamed(keep_logs);
  if (o.out_dir.empty())
    o.out_dir = std::string(BEFT_SOURCE_DIR) + "/logs/experiment-" + std::filesystem::path(o.file).stem().string();
  o.out_dir = std::filesystem::absolute(o.out_dir).lexically_normal().string();
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  beft::experiment::RunnerOptions options;
  options.jobs = beft::experiment::defaultJobs();
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return beft::experiment::runExperiment(options);
}

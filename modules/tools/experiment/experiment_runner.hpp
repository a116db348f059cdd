// beft-experiment from the file to the summary: the scenes generated, the
// episodes not yet done run in the local pool or on Slurm, episodes.csv and
// the summary written and printed.
#pragma once

#include <string>

#include "tools/experiment/log_policy.hpp"
#include "tools/experiment/slurm_script.hpp"

namespace beft::experiment {

struct RunnerOptions {
  std::string file, out_dir;
  int jobs = 1;
  bool retry_failed = false;
  bool list_only = false;  // --list: say what would run, run nothing
  KeepLogs keep_logs = KeepLogs::unsuccessful;  // --keep-logs
  bool slurm = false;      // --slurm: an sbatch array job instead of the local pool
  bool slurm_wait = false;  // --slurm-wait: wait for the job, then gather its rows
  SlurmLimits limits;
  std::string run_episode;  // --run-episode ID: that episode alone, as a Slurm task runs it
};

// The program's exit code: 0 when every episode is done, 1 when some failed,
// 2 for a bad experiment file (or --slurm without Slurm's commands), 130
// when interrupted. --slurm without --slurm-wait: 0 once the job is submitted.
int runExperiment(const RunnerOptions& options);

}  // namespace beft::experiment

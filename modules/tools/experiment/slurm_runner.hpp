// Runs an experiment's missing episodes on a Slurm cluster: an array job, one
// task per episode, each task the same one-episode run as the local pool's
// (beft-experiment --run-episode ID), writing into the experiment's folder,
// which must be on a file system the cluster's nodes share.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tools/experiment/local_pool.hpp"
#include "tools/experiment/slurm_script.hpp"

namespace beft::experiment {

struct SlurmRun {
  SlurmLimits limits;
  bool wait = false;  // wait for the job's end, then gather its rows
  std::string name, out_dir;
  std::vector<std::string> task_command;  // beft-experiment FILE --out OUT --keep-logs K --run-episode (the id appended)
};

struct SlurmOutcome {
  bool gather = false;  // the job has ended (or nothing was to run): the rows are there to gather
  int exit_code = 0;    // the program's, when not gathering
  PoolOutcome pool;     // what the job did, counted as the local pool counts
};

// Whether sbatch and squeue are on PATH; if not, says on stderr which are missing.
bool haveSlurmCommands();

// Submits the jobs unless a job submitted before is still in the queue (its
// id in OUT/slurm/job.txt), then waits for it if asked. Needs sbatch and
// squeue on PATH (exit code 2 without them).
SlurmOutcome runOnSlurm(const std::vector<PoolJob>& jobs, const SlurmRun& run,
                        const std::function<void(const std::string&)>& say);

}  // namespace beft::experiment

// The sbatch script of an experiment's missing episodes: an array job, one
// task per episode, each task running beft-experiment --run-episode ID.
#pragma once

#include <string>
#include <vector>

namespace beft::experiment {

struct SlurmLimits {
  std::string partition;  // empty: the cluster's default partition
  int time_limit_min = 0;  // each task's; 0: the partition's default
  int mem_mb = 0;          // each task's; 0: the partition's default
  int cpus_per_task = 2;   // a run is several processes (simulator, planner, experts)
};

struct BatchJob {
  std::string name;                       // the job's name
  std::string work_dir;                   // the experiment's folder; the tasks' output goes to its slurm/
  std::vector<std::string> task_command;  // the command each task runs, its episode's id appended
  std::vector<std::string> ids;           // the episodes, task i runs ids[i]
};

// The script's text. The ids are in the script itself: sbatch keeps its own
// copy, so a later submission's list cannot shift the tasks of this one.
std::string batchScript(const BatchJob& job, const SlurmLimits& limits);

// A word for the shell: 'text', any ' in it escaped.
std::string shellQuoted(const std::string& text);

}  // namespace beft::experiment

// Runs episodes on this machine, at most `jobs` at once. On SIGINT or SIGTERM
// it stops its running episodes and records nothing for them: they are
// missing, and run again when the experiment is started again.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tools/experiment/log_policy.hpp"

namespace beft::experiment {

struct PoolJob {
  std::string id, folder;
  std::vector<std::string> command;
  std::vector<std::string> recorded;  // the command as episode.json keeps it
  KeepLogs keep_logs = KeepLogs::all;  // whether its run log stays once it succeeded
};

// Simulated seconds per wall second over a stretch of the pool.
struct Pace {
  int episodes = 0;         // done in the stretch
  double simulated_s = 0;   // their simulated time
  double wall_s = 0;        // the stretch's wall time
  double rate() const { return wall_s > 0 ? simulated_s / wall_s : 0; }
};

struct PoolOutcome {
  int done = 0, failed = 0;
  bool interrupted = false;
  double wall_s = 0;          // the pool's time, first start to last end
  double episode_wall_s = 0;  // the sum of the episodes' own times
  // With more than one job and more episodes than jobs, the first episode
  // runs alone (one job's pace on this machine, now) and the rest side by
  // side: the pool's speed-up over one job is pooled.rate() / alone.rate().
  Pace alone, pooled;
  std::string alone_id;
  bool hasSpeedUp() const { return alone.episodes > 0 && pooled.episodes > 0 && alone.rate() > 0; }
};

PoolOutcome runLocalPool(const std::vector<PoolJob>& jobs, int max_jobs,
                         const std::function<void(const std::string&)>& say);

// The default --jobs: half the cores (the other half for each run's
// processes), at least one.
int defaultJobs();

}  // namespace beft::experiment

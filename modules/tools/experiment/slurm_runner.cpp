#include "tools/experiment/slurm_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "tools/experiment/episode_run.hpp"
#include "tools/experiment/scenes.hpp"
#include "tools/experiment/slurm_queue.hpp"
#include "tools/experiment/stop_signals.hpp"

namespace beft::experiment {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using Say = std::function<void(const std::string&)>;

struct Programs {
  std::string sbatch, squeue;
};

std::string readJobId(const fs::path& file) {
  std::ifstream in(file);
  std::string id;
  in >> id;
  return id;
}

// The episodes whose episode.json was written since the job's submission
// (a failed one run again with --retry-failed has an older one).
int endedCount(const std::vector<PoolJob>& jobs, const fs::path& job_file) {
  std::error_code error;
  const auto submitted = fs::last_write_time(job_file, error);
  int ended = 0;
  for (const auto& job : jobs) {
    const auto written = fs::last_write_time(fs::path(job.folder) / kEpisodeFile, error);
    ended += !error && written >= submitted;
  }
  return ended;
}

// Polls squeue, seldom once the job has run a while, until the job has left
// the queue or a stop signal came (false then).
bool waitForJob(const Programs& slurm, const std::string& job_id, const std::vector<PoolJob>& jobs,
                const fs::path& dir, const Say& say) {
  catchStopSignals();
  say("waiting for job " + job_id + " (Ctrl-C stops waiting, not the job)");
  int said = -1;
  for (int poll = 1; !stopRequested(); ++poll) {
    const InQueue queued = jobInQueue(slurm.squeue, job_id, (dir / "squeue.txt").string());
    const int ended = endedCount(jobs, dir / "job.txt");
    if (ended != said)
      say("job " + job_id + ": " + std::to_string(ended) + " of " + std::to_string(jobs.size()) + " episode(s) ended");
    said = ended;
    if (queued == InQueue::no) return true;
    if (queued == InQueue::unknown && poll % 10 == 1)
      say("squeue failed: " + lastLineOf((dir / "squeue.txt").string()));
    const auto until = Clock::now() + std::chrono::seconds(std::min(poll, 30));
    while (!stopRequested() && Clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

// The job's episodes, counted from their episode.json as the pool counts its own.
PoolOutcome counted(const std::vector<PoolJob>& jobs, const std::string& job_id, bool ended, double wall_s,
                    const Say& say) {
  PoolOutcome outcome;
  outcome.interrupted = !ended;
  outcome.wall_s = wall_s;
  std::vector<std::string> missing;
  for (const auto& job : jobs) {
    const EpisodeState state = readEpisodeState(job.folder);
    outcome.done += state.status == Status::done;
    outcome.failed += state.status == Status::failed;
    outcome.episode_wall_s += state.wall_s;
    if (state.status == Status::missing) missing.push_back(job.id);
  }
  if (!missing.empty() && ended)
    say(std::to_string(missing.size()) + " episode(s) of job " + job_id + " ended without a result (a time limit, " +
        "a cancelled task, a node's failure: slurm/task-" + job_id + "_*.txt says), the first " + missing[0] +
        ": start the experiment again to run them");
  return outcome;
}

// The list of the episodes, the script, and the job submitted: its id, or "" (said why).
std::string submit(const std::vector<PoolJob>& jobs, const SlurmRun& run, const Programs& slurm, const fs::path& dir) {
  BatchJob batch{run.name, run.out_dir, run.task_command, {}};
  std::ofstream list(dir / "missing.txt");
  for (const auto& job : jobs) {
    batch.ids.push_back(job.id);
    list << job.id << "\n";
  }
  std::ofstream(dir / "job.sbatch") << batchScript(batch, run.limits);
  std::string error;
  const auto id = submitJob(slurm.sbatch, (dir / "job.sbatch").string(), (dir / "sbatch.txt").string(), error);
  if (!id) std::fprintf(stderr, "[experiment] error: sbatch refused the job (%s): %s\n", (dir / "job.sbatch").c_str(),
                        error.c_str());
  if (id) std::ofstream(dir / "job.txt") << *id << "\n";
  return id.value_or("");
}

std::string limitsText(const SlurmLimits& limits) {
  return "partition " + (limits.partition.empty() ? std::string("(default)") : limits.partition) + ", time limit " +
         (limits.time_limit_min > 0 ? std::to_string(limits.time_limit_min) + " min" : std::string("(default)")) +
         ", memory " + (limits.mem_mb > 0 ? std::to_string(limits.mem_mb) + " MB" : std::string("(default)")) +
         ", " + std::to_string(limits.cpus_per_task) + " CPUs per task";
}

// A job submitted before and still in the queue holds the missing episodes:
// it is waited for, not submitted again.
std::string jobStillQueued(const Programs& slurm, const fs::path& dir) {
  const std::string id = readJobId(dir / "job.txt");
  if (id.empty() || jobInQueue(slurm.squeue, id, (dir / "squeue.txt").string()) != InQueue::yes) return "";
  return id;
}

}  // namespace

bool haveSlurmCommands() {
  std::string missing;
  for (const char* command : {"sbatch", "squeue"})
    if (findOnPath(command).empty()) missing += std::string(" ") + command;
  if (!missing.empty())
    std::fprintf(stderr, "[experiment] error: --slurm needs Slurm's commands on PATH; not found:%s\n",
                 missing.c_str());
  return missing.empty();
}

SlurmOutcome runOnSlurm(const std::vector<PoolJob>& jobs, const SlurmRun& run, const Say& say) {
  if (!haveSlurmCommands()) return {false, 2, {}};
  const Programs slurm{findOnPath("sbatch"), findOnPath("squeue")};
  const fs::path dir = fs::path(run.out_dir) / "slurm";
  fs::create_directories(dir);
  std::string job_id = jobStillQueued(slurm, dir);
  if (!job_id.empty()) say("job " + job_id + ", submitted before, is still in the queue: nothing submitted");
  if (job_id.empty() && jobs.empty()) return {true, 0, {}};
  const auto start = Clock::now();
  if (job_id.empty()) {
    job_id = submit(jobs, run, slurm, dir);
    if (job_id.empty()) return {false, 1, {}};
    say("submitted job " + job_id + ": " + std::to_string(jobs.size()) + " task(s), one per episode (" +
        limitsText(run.limits) + "); their output in " + dir.string() + "/task-" + job_id + "_*.txt");
  }
  if (!run.wait) {
    say("not waiting (--slurm-wait waits): start the same command again once job " + job_id +
        " has ended to gather the rows; it submits nothing while the job is in the queue");
    return {false, 0, {}};
  }
  const bool ended = waitForJob(slurm, job_id, jobs, dir, say);
  const double wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  if (!ended) say("stopped waiting: job " + job_id + " goes on (scancel " + job_id + " ends it)");
  return {true, 0, counted(jobs, job_id, ended, wall_s, say)};
}

}  // namespace beft::experiment

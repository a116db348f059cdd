#include "tools/experiment/local_pool.hpp"

#include <signal.h>
#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <thread>

#include "tools/experiment/child_process.hpp"
#include "tools/experiment/episode_run.hpp"
#include "tools/experiment/stop_signals.hpp"

namespace beft::experiment {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Running {
  const PoolJob* job;
  Clock::time_point start;
};

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A clean folder (what an interrupted run left is gone) with beft-run started in it.
pid_t start(const PoolJob& job) {
  fs::remove_all(job.folder);
  fs::create_directories(job.folder);
  return startProgram(job.command, (fs::path(job.folder) / kRunOutput).string());
}

// Records an ended episode (unless the pool is stopping: then it is left
// missing); its simulated time, when done, goes to `pace`.
void finish(const Running& run, int status, PoolOutcome& outcome, Pace& pace,
            const std::function<void(const std::string&)>& say) {
  const double wall_s = secondsSince(run.start);
  if (stopRequested()) return;
  EpisodeState state = finishedState(run.job->folder, exitCodeOf(status), wall_s);
  state.command = run.job->recorded;
  state.log_removed = applyLogPolicy(run.job->folder, state, run.job->keep_logs);  // before episode.json: crash-only
  writeEpisodeState(run.job->folder, state);
  outcome.episode_wall_s += wall_s;
  char seconds[32];
  std::snprintf(seconds, sizeof(seconds), "%.1f s", wall_s);
  if (state.status == Status::done) {
    ++outcome.done;
    ++pace.episodes;
    pace.simulated_s += state.simulated_s;
    say("done " + run.job->id + " (" + seconds + ")");
  } else {
    ++outcome.failed;
    say("FAILED " + run.job->id + " (" + seconds + "): " + state.reason);
  }
}

void stopAll(const std::map<pid_t, Running>& running) {
  for (const auto& [pid, run] : running) kill(pid, SIGTERM);
}

}  // namespace

int defaultJobs() {
  const unsigned cores = std::thread::hardware_concurrency();
  return cores >= 2 ? static_cast<int>(cores / 2) : 1;
}

PoolOutcome runLocalPool(const std::vector<PoolJob>& jobs, int max_jobs,
                         const std::function<void(const std::string&)>& say) {
  catchStopSignals();
  PoolOutcome outcome;
  const auto pool_start = Clock::now();
  std::map<pid_t, Running> running;
  size_t next = 0;
  bool stopping = false;
  // The first episode alone, for one job's pace, when a pool follows it.
  bool alone_pending = max_jobs > 1 && jobs.size() > static_cast<size_t>(max_jobs);
  auto stretch_start = pool_start;
  while (next < jobs.size() || !running.empty()) {
    const size_t room = static_cast<size_t>(alone_pending ? 1 : max_jobs);
    while (!stopRequested() && next < jobs.size() && running.size() < room) {
      const pid_t pid = start(jobs[next]);
      if (pid > 0) running[pid] = {&jobs[next], Clock::now()};
      if (pid < 0) say("cannot start beft-run for " + jobs[next].id);
      if (pid < 0 && next == 0) alone_pending = false;
      ++next;
    }
    if (stopRequested() && !stopping) {
      stopping = true;
      say("stopping: the running episodes are ended and left to run again");
      stopAll(running);
    }
    if (running.empty()) break;
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0 && errno == ECHILD) break;
    if (pid < 0) continue;  // EINTR: a stop signal, seen above
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const bool was_alone = alone_pending && it->second.job == &jobs[0];
    finish(it->second, status, outcome, was_alone ? outcome.alone : outcome.pooled, say);
    running.erase(it);
    if (was_alone) {
      alone_pending = false;
      outcome.alone_id = jobs[0].id;
      outcome.alone.wall_s = secondsSince(stretch_start);
      stretch_start = Clock::now();
    }
  }
  outcome.interrupted = stopRequested();
  outcome.wall_s = secondsSince(pool_start);
  if (!outcome.alone_id.empty()) outcome.pooled.wall_s = secondsSince(stretch_start);
  return outcome;
}

}  // namespace beft::experiment

#include "lib/launch/supervisor.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <functional>
#include <thread>

#include "lib/wire/run_identity.hpp"

namespace beft::launch {

namespace {

// The child that records the run (beft-record), started first and stopped last.
constexpr const char* kRecorderName = "logger";

std::atomic<bool> g_interrupted{false};
void onSignal(int) { g_interrupted = true; }

using Clock = std::chrono::steady_clock;

// In the child, before exec: the threads the program starts inherit both.
// Lowering a priority needs no privilege; a failure is said and run through.
// BEFT_BACKGROUND=0 keeps every process at the normal priority (to measure
// what the background costs or saves).
void applyPriority(Priority priority) {
  if (priority != Priority::Background) return;
  if (const char* setting = std::getenv("BEFT_BACKGROUND"); setting && std::string(setting) == "0") return;
  constexpr int kBackgroundNice = 10;
  errno = 0;
  const int nice_now = getpriority(PRIO_PROCESS, 0);
  if (errno == 0 && nice_now < kBackgroundNice && setpriority(PRIO_PROCESS, 0, kBackgroundNice) != 0)
    std::fprintf(stderr, "cannot lower the priority to nice %d: %s\n", kBackgroundNice, std::strerror(errno));
  const sched_param no_priority{};
  if (sched_setscheduler(0, SCHED_BATCH, &no_priority) != 0)
    std::fprintf(stderr, "cannot set SCHED_BATCH: %s\n", std::strerror(errno));
}

struct Child {
  ProcessSpec spec;
  std::vector<std::string> argv;
  pid_t pid = -1;
  int output_fd = -1;  // read end of the child's stdout+stderr
  std::string pending;  // output not yet ended by a newline
  int restarts = 0;
  bool running = false;
  bool finished = false;  // exited and will not be restarted
  Clock::time_point restart_at{};
  bool restart_scheduled = false;
};

class Printer {
 public:
  Printer(bool quiet, const std::string& file) : quiet_(quiet) {
    if (!file.empty()) file_.open(file, std::ios::app);
  }
  void line(const std::string& name, const std::string& text) {
    const std::string out = "[" + name + "] " + text + "\n";
    if (!quiet_) {
      std::fputs(out.c_str(), stdout);
      std::fflush(stdout);
    }
    if (file_) file_ << out << std::flush;
  }
  // The launcher's own lines are always shown.
  void own(const std::string& text) {
    const std::string out = "[launch] " + text + "\n";
    std::fputs(out.c_str(), stdout);
    std::fflush(stdout);
    if (file_) file_ << out << std::flush;
  }

 private:
  bool quiet_;
  std::ofstream file_;
};

std::string resolveCommand(const std::string& command, const std::string& bin_dir) {
  if (command.find('/') != std::string::npos) return command;
  if (!bin_dir.empty()) {
    const std::string candidate = bin_dir + "/" + command;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return command;  // execvp searches PATH
}

bool start(Child& child, Printer& printer) {
  int fds[2];
  if (pipe(fds) != 0) {
    printer.own("cannot create a pipe for " + child.spec.name + ": " + std::strerror(errno));
    return false;
  }
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    printer.own("cannot fork " + child.spec.name + ": " + std::strerror(errno));
    close(fds[0]);
    close(fds[1]);
    return false;
  }
  if (pid == 0) {
    // The child: own process group, dies with the launcher, output to the pipe.
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(1);
    dup2(fds[1], STDOUT_FILENO);
    dup2(fds[1], STDERR_FILENO);
    close(fds[0]);
    close(fds[1]);
    applyPriority(child.spec.priority);
    std::vector<char*> argv;
    for (auto& arg : child.argv) argv.push_back(arg.data());
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    std::fprintf(stderr, "cannot execute '%s': %s\n", argv[0], std::strerror(errno));
    _exit(127);
  }
  close(fds[1]);
  fcntl(fds[0], F_SETFL, fcntl(fds[0], F_GETFL) | O_NONBLOCK);
  child.pid = pid;
  child.output_fd = fds[0];
  child.running = true;
  child.pending.clear();
  return true;
}

void drain(Child& child, Printer& printer, bool flush_partial) {
  if (child.output_fd < 0) return;
  char buffer[4096];
  while (true) {
    const ssize_t n = read(child.output_fd, buffer, sizeof(buffer));
    if (n <= 0) break;
    child.pending.append(buffer, static_cast<std::size_t>(n));
  }
  std::size_t newline;
  while ((newline = child.pending.find('\n')) != std::string::npos) {
    printer.line(child.spec.name, child.pending.substr(0, newline));
    child.pending.erase(0, newline + 1);
  }
  if (flush_partial && !child.pending.empty()) {
    printer.line(child.spec.name, child.pending);
    child.pending.clear();
  }
}

std::string describeStatus(int status) {
  if (WIFEXITED(status)) return "exited with code " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return std::string("killed by signal ") + strsignal(WTERMSIG(status));
  return "ended";
}

// The recorder creates its file once it listens: nothing is started before
// that, so the log holds the run from its first message.
bool waitForRecorder(Child& recorder, const std::string& path, Printer& printer) {
  const auto give_up = Clock::now() + std::chrono::seconds(10);
  std::error_code error;
  while (Clock::now() < give_up) {
    if (std::filesystem::exists(path, error)) return true;
    int status = 0;
    if (waitpid(recorder.pid, &status, WNOHANG) == recorder.pid) {
      recorder.running = false;
      drain(recorder, printer, true);
      printer.own("the recorder " + describeStatus(status) + " before it started recording");
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  printer.own("the recorder did not create " + path + " within 10 s");
  return false;
}

// SIGTERM, then SIGKILL after the grace time, to the children `chosen` picks.
void stopSome(std::vector<Child>& children, Printer& printer, double grace_s,
              const std::function<bool(const Child&)>& chosen) {
  for (auto& child : children)
    if (child.running && chosen(child)) kill(-child.pid, SIGTERM);
  const auto deadline = Clock::now() + std::chrono::duration<double>(grace_s);
  while (Clock::now() < deadline) {
    bool any = false;
    for (auto& child : children) {
      if (!child.running || !chosen(child)) continue;
      drain(child, printer, false);
      int status = 0;
      if (waitpid(child.pid, &status, WNOHANG) == child.pid) {
        child.running = false;
        drain(child, printer, true);
      } else {
        any = true;
      }
    }
    if (!any) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  for (auto& child : children) {
    if (!child.running || !chosen(child)) continue;
    printer.own(child.spec.name + " did not stop within " + std::to_string(grace_s) + " s: killed");
    kill(-child.pid, SIGKILL);
    waitpid(child.pid, nullptr, 0);
    child.running = false;
  }
}

// Listeners first (the SSR bridge: it may still ask the blackboard for the
// state it ends on), the recorder last, so it records what the others send
// while stopping.
void stopAll(std::vector<Child>& children, Printer& printer, double grace_s) {
  stopSome(children, printer, grace_s, [](const Child& child) { return child.spec.group == "listener"; });
  stopSome(children, printer, grace_s, [](const Child& child) { return child.spec.name != kRecorderName; });
  stopSome(children, printer, grace_s, [](const Child& child) { return child.spec.name == kRecorderName; });
  for (auto& child : children)
    if (child.output_fd >= 0) {
      drain(child, printer, true);
      close(child.output_fd);
      child.output_fd = -1;
    }
}

}  // namespace

std::string commandLineOf(const ProcessSpec& process, const SupervisorOptions& options) {
  std::string line = options.run_id != 0 ? "BEFT_RUN_ID=" + wire::runIdText(options.run_id) + " " : "";
  if (!options.key_file.empty()) line += "BEFT_KEY_FILE='" + options.key_file + "' ";
  // The arbiter's beacons name the launch, so that the other hosts can join the run.
  if (const std::string origin = wire::runOriginAssignments(options.run_origin); process.is_arbiter && !origin.empty())
    line += origin + " ";
  line += resolveCommand(process.command, options.bin_dir);
  for (const auto& arg : process.args) line += " " + arg;
  if (process.append_lcm_url) line += " --lcm-url '" + options.lcm_url + "'";
  return line;
}

namespace {

// The recorder first, when the run is recorded, then each process of this host.
std::vector<Child> childrenToStart(const LaunchSpec& spec, const SupervisorOptions& options, Printer& printer) {
  std::vector<Child> children;
  if (!options.record_log.empty()) {
    // Replaced anyway (--force); gone now so that its appearance means the recorder listens.
    std::error_code error;
    std::filesystem::remove(options.record_log, error);
    Child logger;
    logger.spec.name = kRecorderName;
    // Off the control loop: it never preempts the run and catches up when a core is free.
    logger.spec.priority = Priority::Background;
    logger.argv = {resolveCommand("beft-record", options.bin_dir), "--force", "--quiet"};
    if (!options.lcm_url.empty()) logger.argv.push_back("--lcm-url=" + options.lcm_url);
    if (!options.record_exclude_regex.empty()) logger.argv.push_back("--exclude=" + options.record_exclude_regex);
    if (options.record_camera != "all") logger.argv.push_back("--camera=" + options.record_camera);
    logger.argv.push_back(options.record_log);
    children.push_back(logger);
  }
  for (const auto& process : spec.processes) {
    if (process.host != options.host) {
      printer.own("not starting " + process.name + ": it runs on host '" + process.host + "'");
      continue;
    }
    if (options.except.count(process.name)) {
      printer.own("not starting " + process.name + " (--except); start it by hand with:\n    " +
                  commandLineOf(process, options));
      continue;
    }
    Child child;
    child.spec = process;
    child.argv.push_back(resolveCommand(process.command, options.bin_dir));
    child.argv.insert(child.argv.end(), process.args.begin(), process.args.end());
    if (process.append_lcm_url) {
      child.argv.push_back("--lcm-url");
      child.argv.push_back(options.lcm_url);
    }
    children.push_back(child);
  }
  return children;
}

// A process that died (not one that exited with a code, or was told to stop).
bool crashed(int status) {
  return WIFSIGNALED(status) && WTERMSIG(status) != SIGTERM && WTERMSIG(status) != SIGINT;
}

// Restarted processes resume from the run's log (crash-only): the same
// process, with --resume-log, rebuilds the state it had.
void scheduleRestart(Child& child, int status, const SupervisorOptions& options, Printer& printer) {
  ++child.restarts;
  const bool resume = !options.record_log.empty();
  if (resume && std::find(child.argv.begin(), child.argv.end(), "--resume-log") == child.argv.end()) {
    child.argv.push_back("--resume-log");
    child.argv.push_back(options.record_log);
  }
  printer.own(child.spec.name + " " + describeStatus(status) + ": restarting (" + std::to_string(child.restarts) +
              "/" + std::to_string(child.spec.max_restarts) + ")" +
              (resume ? ", resuming from the run's log" : ", without a log to resume from: its state is lost"));
  child.restart_scheduled = true;
  child.restart_at = Clock::now() + std::chrono::milliseconds(500);
}

// One child that exited: the arbiter ends the run (true) unless it crashed
// and may be restarted; the recorder's death ends it too (the log would lose
// messages); another is restarted by its policy, or left finished.
bool onChildExit(Child& child, int status, const SupervisorOptions& options, Printer& printer, RunOutcome& outcome) {
  child.running = false;
  drain(child, printer, true);
  close(child.output_fd);
  child.output_fd = -1;
  const bool failed = !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  const bool may_restart = child.spec.restart == RestartPolicy::OnFailure && child.restarts < child.spec.max_restarts;
  if (child.spec.name == kRecorderName) {
    outcome.log_incomplete = true;
    outcome.message = "the recorder " + describeStatus(status) + ": the run's log is incomplete";
    printer.own(outcome.message + "; stopping the run");
    return true;
  }
  if (child.spec.is_arbiter && !(crashed(status) && may_restart)) {
    outcome.arbiter_exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    printer.own("arbiter " + describeStatus(status) + ": the run is over");
    return true;
  }
  if (failed && may_restart) {
    scheduleRestart(child, status, options, printer);
  } else {
    printer.own(child.spec.name + " " + describeStatus(status) +
                (failed && child.spec.restart == RestartPolicy::OnFailure ? " (restart limit reached)" : ""));
    child.finished = true;
  }
  return false;
}

// Relays the children's output and watches them until the arbiter ends,
// everything has exited or a signal came.
// Kills planned with --kill, once the run's log shows their tick.
class Killer {
 public:
  explicit Killer(const SupervisorOptions& options) : kills_(options.kills) {
    // Only when kills are planned: the launcher otherwise holds no LCM instance of its own.
    if (!kills_.empty()) follower_ = std::make_unique<TickFollower>(options.lcm_url, options.run_id);
  }
  void check(std::vector<Child>& children, Printer& printer) {
    if (std::all_of(kills_.begin(), kills_.end(), [](const PlannedKill& k) { return k.done; })) return;
    const int64_t tick = follower_->poll();
    for (auto& planned : kills_) {
      if (planned.done || tick < planned.tick) continue;
      for (auto& child : children) {
        if (child.spec.name != planned.process || !child.running) continue;
        printer.own("killing " + child.spec.name + " (SIGKILL) at tick " + std::to_string(tick) + " as asked (--kill)");
        ::kill(-child.pid, SIGKILL);
      }
      planned.done = true;
    }
  }

 private:
  std::vector<PlannedKill> kills_;
  std::unique_ptr<TickFollower> follower_;
};

void watchChildren(std::vector<Child>& children, const SupervisorOptions& options, Printer& printer,
                   RunOutcome& outcome) {
  Killer killer(options);
  while (true) {
    if (g_interrupted) {
      outcome.interrupted = true;
      outcome.message = "interrupted";
      printer.own("interrupted: stopping every process");
      return;
    }
    std::vector<pollfd> fds;
    for (auto& child : children)
      if (child.output_fd >= 0) fds.push_back({child.output_fd, POLLIN, 0});
    poll(fds.data(), fds.size(), 50);
    for (auto& child : children) drain(child, printer, false);
    killer.check(children, printer);
    bool arbiter_done = false;
    for (auto& child : children) {
      int status = 0;
      if (!child.running || waitpid(child.pid, &status, WNOHANG) != child.pid) continue;
      arbiter_done |= onChildExit(child, status, options, printer, outcome);
    }
    if (arbiter_done) return;
    for (auto& child : children)
      if (child.restart_scheduled && Clock::now() >= child.restart_at) {
        child.restart_scheduled = false;
        if (!start(child, printer)) child.finished = true;
      }
    bool any_alive = false;
    for (auto& child : children) any_alive |= child.running || child.restart_scheduled;
    if (!any_alive) {
      outcome.message = "every process has exited";
      return;
    }
  }
}

}  // namespace

RunOutcome supervise(const LaunchSpec& spec, const SupervisorOptions& options) {
  g_interrupted = false;
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  signal(SIGPIPE, SIG_IGN);

  Printer printer(options.quiet_children, options.output_file);
  RunOutcome outcome;
  // Every process of the run stamps its messages with the run id and refuses another run's.
  if (options.run_id != 0) setenv("BEFT_RUN_ID", wire::runIdText(options.run_id).c_str(), 1);
  // Every process of a keyed run tags what it publishes and refuses what lacks a valid tag.
  if (!options.key_file.empty()) setenv("BEFT_KEY_FILE", options.key_file.c_str(), 1);
  else unsetenv("BEFT_KEY_FILE");
  wire::setRunOriginEnvironment(options.run_origin);
  std::vector<Child> children = childrenToStart(spec, options, printer);
  for (auto& child : children) {
    if (!start(child, printer)) {
      outcome.message = "could not start " + child.spec.name;
      stopAll(children, printer, options.stop_grace_s);
      return outcome;
    }
    if (child.spec.is_arbiter) outcome.arbiter_ran = true;
    if (child.spec.name == kRecorderName && !waitForRecorder(child, options.record_log, printer)) {
      outcome.message = "the recorder did not start";
      stopAll(children, printer, options.stop_grace_s);
      return outcome;
    }
  }
  printer.own("started " + std::to_string(children.size()) + " processes on " + options.lcm_url +
              (options.run_id != 0 ? " as " + wire::describeRun(options.run_id) : ""));
  if (!options.key_file.empty())
    printer.own("the run is keyed (" + options.key_file +
                "): every process tags its messages and refuses those without a valid tag");
  watchChildren(children, options, printer, outcome);
  stopAll(children, printer, options.stop_grace_s);
  if (outcome.message.empty() && outcome.arbiter_exit_code >= 0)
    outcome.message = outcome.arbiter_exit_code == 0 ? "run finished" : "run failed";
  return outcome;
}

}  // namespace beft::launch

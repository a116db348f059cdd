// One way to write a process that serves rather than fires (the planner, the
// blackboard, the recorder, the arbiter): a class that says what it is,
// declares what it reads and writes as port members (ports.hpp) and which
// options it takes, and a serve() loop. The runner around it does what every
// such process needs: the command line with --help, --interface, --lcm-url
// and --name, heap retention, logging, LCM, and SIGINT/SIGTERM.
#pragma once

#include <atomic>
#include <chrono>
#include <string>
#include <vector>

#include <beft/heartbeat_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/service/ports.hpp"

namespace CLI {
class App;
}
namespace lcm {
class LCM;
}

namespace beft::service {

// What stops a service: SIGINT (counted: the arbiter ends the run after the
// tick on the first, at once on the second) and SIGTERM.
struct StopSignals {
  std::atomic<int> interrupts{0};
  std::atomic<bool> terminated{false};
  bool any() const { return interrupts.load() > 0 || terminated.load(); }
};

struct Context {
  lcm::LCM& lcm;
  std::string lcm_url;
  std::string process_name;
  StopSignals& stop;
  // Set when the process was restarted after a crash (--resume-log): the
  // run's log, from which the service rebuilds what it held.
  std::string resume_log;
};

// What it reads and writes (reads(), writes()) comes from its ports.
class Service : public PortSet {
 public:
  virtual std::string name() const = 0;         // default process name, e.g. "planner"
  virtual std::string description() const = 0;  // the paragraph of --help
  // Its own command-line options.
  virtual void addOptions(CLI::App& app) { (void)app; }
  // After parsing, before LCM: check the options, build the logic. Throw
  // std::invalid_argument (or another std::exception) for bad input: exit 2.
  virtual void onStartUp() {}
  // Serves until context.stop says so or the work is done; the exit code.
  virtual int serve(Context& context) = 0;
  // Whether it can be restarted after a crash with --resume-log (all but the
  // recorder, whose log is what the others resume from).
  virtual bool resumable() const { return true; }
  // Whether it belongs to one run; the recorder takes every run.
  virtual bool belongsToARun() const { return true; }
};

// The whole main() of a service process:
//   int main(int argc, char** argv) { Planner p; return beft::service::runServiceMain(argc, argv, p); }
int runServiceMain(int argc, char** argv, Service& service);

// What --interface prints.
std::string interfaceText(const Service& service, const std::string& process_name);

// Heartbeats of a service the run waits for (the planner): one every period,
// and one at once (at most every 50 ms) when an arbiter says it waits, as
// the experts answer, so a run never waits a period for it.
class HeartbeatSender {
 public:
  HeartbeatSender(lcm::LCM& lcm, const WritePort<beft::heartbeat_t>& port, const std::string& process_name,
                  double period_s = 1.0);
  // Call on every turn of the service's loop.
  void update(bool arbiter_waiting);
  int sent() const { return sent_; }

 private:
  using Clock = std::chrono::steady_clock;
  lcm::LCM& lcm_;
  const WritePort<beft::heartbeat_t>& port_;
  beft::heartbeat_t heartbeat_{};
  Clock::duration period_;
  Clock::time_point next_;
  Clock::time_point last_waiting_answer_;
  int sent_ = 0;
};

}  // namespace beft::service

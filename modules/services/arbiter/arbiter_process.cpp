#include "services/arbiter/arbiter_process.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "lib/common/channels.hpp"
#include "services/arbiter/firing_log.hpp"
#include "services/arbiter/lcm_arbiter.hpp"
#include "lib/common/log.hpp"
#include "lib/petri/pnml_reader.hpp"
#include "services/arbiter/resume_point.hpp"

namespace beft::arbiter {

namespace {

// Exit codes: 0 when the run FINISHED, 1 when it FAILED, 2 on bad input.
void logSummary(const ArbiterCore& core) {
  const ArbiterStats& s = core.stats();
  log::info(runStateName(core.state()), ": ", core.message(), " | ticks ", s.ticks_completed, ", firings ",
            s.firings_started, " (done ", s.firings_done, ", retries ", s.retries, ", skips ", s.skips,
            "), FIRE re-sends ", s.fire_resends, ", dropped DONEs: ", s.duplicate_dones, " duplicate, ",
            s.late_dones, " late, ", s.unknown_dones, " unknown");
}

}  // namespace

std::string ArbiterProcess::description() const {
  return "Petri-net arbiter: fires the experts named in a PNML net, in lockstep ticks.\n"
         "Waits for a heartbeat of every expert in the net, then each step starts every enabled\n"
         "transition (FIRE, re-sent until DONE) and ends it on DONE; the tick transition opens the\n"
         "next tick. Timeouts, lost heartbeats and failures apply the net's policy (retry, skip,\n"
         "fail). Prints one line per firing on stdout. RUN_CONTROL (beft-control, a viewer)\n"
         "pauses the run after the current tick, steps it to a given tick or lets it run on; it\n"
         "holds between ticks, so it computes what a run that ran through does, and answers on\n"
         "RUN_CONTROL_STATE. Ctrl-C ends the run after the current tick (held or not), a second\n"
         "Ctrl-C or SIGTERM at once. Exit 0 when the run FINISHED, 1 when it FAILED, 2 on bad\n"
         "input.";
}

ArbiterProcess::ArbiterProcess() {
  include(outlets_);  // FIRE, MARKING, RUN_STATUS first; the beacons after
  include(inbox_);
}

void ArbiterProcess::addOptions(CLI::App& app) {
  net_path_ = std::string(BEFT_SOURCE_DIR) + "/scenarios/nets/default.pnml";
  // BEFT_ARBITER_SPIN_US sets the default, so a benchmark can turn it off for a whole run.
  if (const char* setting = std::getenv("BEFT_ARBITER_SPIN_US"); setting && *setting) spin_us_ = std::atoi(setting);
  app.add_option("--net", net_path_, "PNML net to run")->capture_default_str();
  app.add_option("--max-ticks", config_.max_ticks, "end after this many ticks (0: until STOP_REQUEST)")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  app.add_option("--dt", config_.dt_s, "simulated seconds per tick (FIRE utime = tick * dt)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--startup-timeout", config_.startup_timeout_s, "seconds to wait for the first heartbeat of every expert")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  app.add_option("--wait-for", config_.also_wait_for,
                 "a process outside the net whose first heartbeat the run also waits for, a service the "
                 "experts ask within a tick such as the planner (repeatable): a request sent before it is "
                 "up is lost, and the run's result then depends on how fast the machine started it");
  app.add_option("--heartbeat-timeout", config_.heartbeat_timeout_s,
                 "seconds without heartbeat after which an expert counts as gone, unless its "
                 "transition sets <heartbeat_timeout>")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--resend-period", config_.resend_period_s, "seconds between re-sends of a FIRE")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--spin-us", spin_us_,
                 "while one firing runs (and no other), poll for its DONE this many microseconds before sleeping "
                 "(0: sleep at once); a tick waits for one DONE after another, and waking a sleeping process "
                 "costs more than the poll, on a virtual machine most (env BEFT_ARBITER_SPIN_US)")
      ->capture_default_str()->check(CLI::Range(0, 100000));
  app.add_option("--pace", pace_,
                 "fast: each tick starts as soon as the last has ended; real-time: not before its simulated "
                 "time (tick * dt) has passed on the wall clock since the run, or its last resume, began, for "
                 "a person watching (what the run computes is the same)")
      ->capture_default_str()
      ->check(CLI::IsMember({"fast", "real-time"}));
  app.add_option("--firing-log", firing_log_path_, "also write every firing to this CSV file");
  app.add_flag("--quiet", quiet_, "no line per firing on stdout");
}

void ArbiterProcess::onStartUp() {
  config_.pace = parsePace(pace_);
  try {
    net_ = readPnmlFile(net_path_);
  } catch (const NetError& e) {
    std::string problems;
    for (const auto& problem : e.problems()) problems += (problems.empty() ? "" : "\n") + problem;
    throw std::invalid_argument(problems);
  }
  for (const auto& warning : net_.warnings) log::warn(warning);
  std::string expert_list;
  for (const auto& name : net_.experts()) expert_list += (expert_list.empty() ? "" : " ") + name;
  log::info("net ", net_path_, ": ", net_.places.size(), " places, ", net_.transitions.size(),
            " transitions, experts: ", expert_list.empty() ? "none" : expert_list);
}

int ArbiterProcess::serve(service::Context& context) {
  std::unique_ptr<FiringLog> firing_log;
  std::unique_ptr<ArbiterEventQueue> events;
  try {
    firing_log = std::make_unique<FiringLog>(quiet_ ? nullptr : stdout, firing_log_path_);
    events = std::make_unique<ArbiterEventQueue>(context.lcm, context.lcm_url, inbox_);
  } catch (const std::exception& e) {
    log::error(e.what());
    return 2;
  }
  log::info("receiving: ", events->description());
  // Fully buffered: the firing log flushes its lines every quarter second (and log lines flush it first).
  std::setvbuf(stdout, nullptr, _IOFBF, 1 << 16);
  SteadyClock clock;
  LcmArbiterOutput output(context.lcm, outlets_, firing_log.get());
  ArbiterCore core(std::move(net_), config_, clock, output);
  if (!context.resume_log.empty()) {
    try {
      const int64_t restarted_us = std::chrono::duration_cast<std::chrono::microseconds>(
                                       std::chrono::system_clock::now().time_since_epoch())
                                       .count();
      if (const auto point = readResumePoint(context.resume_log, restarted_us, 3.0))
        core.resume(*point);
      else
        log::info("the run's log holds no MARKING yet: starting the run afresh");
    } catch (const std::exception& e) {
      log::error("cannot resume from ", context.resume_log, ": ", e.what());
      return 2;
    }
  }
  log::info("on ", context.lcm_url, (config_.max_ticks > 0 ? ", " + std::to_string(config_.max_ticks) + " ticks" : ""),
            config_.pace == Pace::kRealTime ? ", real-time pace" : "",
            " (Ctrl-C: end after this tick; twice, or SIGTERM: end now)");
  runArbiterLoop(*events, core, clock, &context.stop, spin_us_);
  firing_log->flush();
  logSummary(core);
  return core.state() == RunState::Finished ? 0 : 1;
}

}  // namespace beft::arbiter

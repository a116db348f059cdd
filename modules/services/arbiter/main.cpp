// beft-arbiter: schedules the experts by a Petri net (PNML), over LCM.
#include <CLI/CLI.hpp>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "arbiter_core.hpp"
#include "firing_log.hpp"
#include "heap_retention.hpp"
#include "lcm_arbiter.hpp"
#include "lcm_url.hpp"
#include "log.hpp"
#include "pnml_reader.hpp"

namespace {

beft::arbiter::StopSignals g_signals;
void onInterrupt(int) { g_signals.interrupts.fetch_add(1); }
void onTerminate(int) { g_signals.terminated.store(true); }

const char* kInterface =
    "process: arbiter\n"
    "reads:\n"
    "  DONE  (beft.done_t, an expert finished a firing)\n"
    "  HEARTBEAT  (beft.heartbeat_t, liveness of the experts named in the net)\n"
    "  STOP_REQUEST  (beft.run_status_t, message = why; the run ends at the end of the tick)\n"
    "writes:\n"
    "  FIRE  (beft.fire_t, re-sent until DONE)\n"
    "  MARKING  (beft.marking_t, after every step)\n"
    "  RUN_STATUS  (beft.run_status_t, at start, every tick, and at the end)\n";

}  // namespace

int main(int argc, char** argv) {
  beft::retainFreedHeapMemory();
  using namespace beft::arbiter;
  beft::log::setProcessName("arbiter");

  std::string net_path = std::string(BEFT_SOURCE_DIR) + "/scenarios/nets/default.pnml";
  std::string lcm_url = beft::defaultLcmUrl();
  std::string firing_log_path;
  ArbiterConfig config;
  bool show_interface = false;
  bool quiet = false;
  // BEFT_ARBITER_SPIN_US sets the default, so a benchmark can turn it off for a whole run.
  int spin_us = 1000;
  if (const char* setting = std::getenv("BEFT_ARBITER_SPIN_US"); setting && *setting) spin_us = std::atoi(setting);

  CLI::App app(
      "Petri-net arbiter: fires the experts named in a PNML net, in lockstep ticks.\n"
      "Waits for a heartbeat of every expert in the net, then each step starts every enabled\n"
      "transition (FIRE, re-sent until DONE) and ends it on DONE; the tick transition opens the\n"
      "next tick. Timeouts, lost heartbeats and failures apply the net's policy (retry, skip,\n"
      "fail). Prints one line per firing on stdout. Ctrl-C ends the run after the current\n"
      "tick, a second Ctrl-C or SIGTERM at once. Exit 0 when the run FINISHED, 1 when it\n"
      "FAILED, 2 on bad input.",
      "beft-arbiter");
  app.add_option("--net", net_path, "PNML net to run")->capture_default_str();
  app.add_option("--lcm-url", lcm_url, "LCM URL (env BEFT_LCM_URL)")->capture_default_str();
  app.add_option("--max-ticks", config.max_ticks, "end after this many ticks (0: until STOP_REQUEST)")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  app.add_option("--dt", config.dt_s, "simulated seconds per tick (FIRE utime = tick * dt)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--startup-timeout", config.startup_timeout_s,
                 "seconds to wait for the first heartbeat of every expert")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  app.add_option("--wait-for", config.also_wait_for,
                 "a process outside the net whose first heartbeat the run also waits for, a service the "
                 "experts ask within a tick such as the planner (repeatable): a request sent before it is "
                 "up is lost, and the run's result then depends on how fast the machine started it");
  app.add_option("--heartbeat-timeout", config.heartbeat_timeout_s,
                 "seconds without heartbeat after which an expert counts as gone, unless its "
                 "transition sets <heartbeat_timeout>")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--resend-period", config.resend_period_s, "seconds between re-sends of a FIRE")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--spin-us", spin_us,
                 "while a firing runs, poll for its DONE this many microseconds before sleeping (0: sleep at "
                 "once); a tick waits for one DONE after another, and waking a sleeping process costs more "
                 "than the poll, on a virtual machine most (env BEFT_ARBITER_SPIN_US)")
      ->capture_default_str()->check(CLI::Range(0, 100000));
  app.add_option("--firing-log", firing_log_path, "also write every firing to this CSV file");
  app.add_flag("--quiet", quiet, "no line per firing on stdout");
  app.add_flag("--interface", show_interface, "print the channels read and written");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (show_interface) {
    std::fputs(kInterface, stdout);
    return 0;
  }

  Net net;
  try {
    net = readPnmlFile(net_path);
  } catch (const NetError& e) {
    for (const auto& problem : e.problems()) std::fprintf(stderr, "%s\n", problem.c_str());
    return 2;
  }
  for (const auto& warning : net.warnings) beft::log::warn(warning);
  const auto experts = net.experts();
  std::string expert_list;
  for (const auto& name : experts) expert_list += (expert_list.empty() ? "" : " ") + name;
  beft::log::info("net ", net_path, ": ", net.places.size(), " places, ", net.transitions.size(),
                  " transitions, experts: ", expert_list.empty() ? "none" : expert_list);

  std::unique_ptr<FiringLog> firing_log;
  try {
    firing_log = std::make_unique<FiringLog>(quiet ? nullptr : stdout, firing_log_path);
  } catch (const std::exception& e) {
    beft::log::error(e.what());
    return 2;
  }

  lcm::LCM lcm(lcm_url);
  if (!lcm.good()) {
    beft::log::error("cannot open LCM at ", lcm_url);
    return 2;
  }
  std::unique_ptr<ArbiterEventQueue> events;
  try {
    events = std::make_unique<ArbiterEventQueue>(lcm, lcm_url);
  } catch (const std::exception& e) {
    beft::log::error("cannot receive on ", lcm_url, ": ", e.what());
    return 2;
  }
  beft::log::info("receiving: ", events->description());
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onTerminate);
  // Fully buffered: the firing log flushes its lines every quarter second (and log lines flush it first).
  std::setvbuf(stdout, nullptr, _IOFBF, 1 << 16);

  SteadyClock clock;
  LcmArbiterOutput output(lcm, firing_log.get());
  ArbiterCore core(std::move(net), config, clock, output);
  beft::log::info("on ", lcm_url, (config.max_ticks > 0 ? ", " + std::to_string(config.max_ticks) + " ticks" : ""),
                  " (Ctrl-C: end after this tick; twice, or SIGTERM: end now)");
  runArbiterLoop(*events, core, clock, &g_signals, spin_us);
  firing_log->flush();

  const ArbiterStats& s = core.stats();
  beft::log::info(runStateName(core.state()), ": ", core.message(), " | ticks ", s.ticks_completed,
                  ", firings ", s.firings_started, " (done ", s.firings_done, ", retries ", s.retries,
                  ", skips ", s.skips, "), FIRE re-sends ", s.fire_resends, ", dropped DONEs: ",
                  s.duplicate_dones, " duplicate, ", s.late_dones, " late, ", s.unknown_dones, " unknown");
  return core.state() == RunState::Finished ? 0 : 1;
}

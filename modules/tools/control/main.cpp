// beft-control: pause a running run, step it tick by tick, let it run on (see --help).
#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "lib/common/clocks.hpp"
#include "lib/common/command_line.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/service/run_control_client.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/run_discovery.hpp"
#include "lib/wire/run_identity.hpp"
#include "tools/control/arbiter_link.hpp"

namespace {

using beft::run_control_t;
using beft::service::RunControlClient;

enum class Action { Pause, Step, Run, Status };

struct Options {
  Action action = Action::Status;
  int64_t ticks = 1;   // step: this many ticks more
  int64_t until = -1;  // step: hold after this tick instead
  std::string lcm_url = beft::defaultLcmUrl();
  std::string run_id;  // "": the one run heard on the URL
  std::string origin = "user";
  double timeout_s = 10.0;
  bool no_wait = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Pause a running BEFT run, step it tick by tick, or let it run on. The arbiter holds between ticks "
      "(the tick under way finishes, the next waits), so a paused or stepped run computes exactly what a run "
      "that ran through does. The request goes out on RUN_CONTROL, again every 0.1 s until the arbiter "
      "answers on RUN_CONTROL_STATE; pause and step then wait until the run holds. Prints the arbiter's "
      "state. Exit 0 done, 1 no answer (no run on the URL?), 2 bad command line, 3 answered but not held "
      "within --timeout.",
      "beft-control");
  app.require_subcommand(1);
  app.add_option("--lcm-url", o.lcm_url, "LCM URL of the running system (env BEFT_LCM_URL)")->capture_default_str();
  app.add_option("--run-id", o.run_id,
                 "the run to control (hex as its channels show it after '@', or 0x...); default: BEFT_RUN_ID, "
                 "else the one run whose heartbeats are heard on the URL");
  app.add_option("--origin", o.origin,
                 "who asks (the arbiter applies each origin's requests in their order; a viewer has its own)")
      ->capture_default_str();
  app.add_option("--timeout", o.timeout_s, "how long to wait for the arbiter's answer, and then for the hold [s]")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_flag("--no-wait", o.no_wait, "pause, step: return once the arbiter has answered, before it holds");
  app.footer(
      "Examples:\n"
      "  beft-control pause              finish the tick under way, then hold\n"
      "  beft-control step               run one more tick, then hold\n"
      "  beft-control step 10            ten more ticks\n"
      "  beft-control step --until 120   hold after tick 120\n"
      "  beft-control run                run on\n"
      "  beft-control status             print where the run is");
  auto* pause = app.add_subcommand("pause", "finish the tick under way, then hold");
  auto* step = app.add_subcommand("step", "run N more ticks (default 1), then hold");
  step->add_option("ticks", o.ticks, "how many ticks")->check(CLI::PositiveNumber);
  step->add_option("--until", o.until, "hold after this tick instead")->check(CLI::NonNegativeNumber);
  auto* run = app.add_subcommand("run", "run on (the pace the arbiter was started with)");
  app.add_subcommand("status", "print the arbiter's state");
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  o.action = *pause ? Action::Pause : *step ? Action::Step : *run ? Action::Run : Action::Status;
  return std::nullopt;
}

void printState(const run_control_t& state) {
  std::printf("%s%s\n", beft::service::describeRunControlState(state).c_str(),
              state.origin.empty() ? ""
                                   : ("; last request from " + state.origin + " (sequence " +
                                      std::to_string(state.sequence) + ")")
                                         .c_str());
}

// The run ended while the tool waited: said, and whether that is what was asked for.
int sayEnded(const beft::run_status_t& status, bool expected) {
  std::printf("the run has ended at tick %lld: %s\n", static_cast<long long>(status.tick), status.message.c_str());
  return expected ? 0 : 1;
}

// Whether the state says the run holds where `wanted` asked it to.
bool holdsAsAsked(const run_control_t& state, const run_control_t& wanted) {
  if (state.mode != run_control_t::MODE_PAUSE) return false;
  return wanted.mode != run_control_t::MODE_STEP || state.tick >= wanted.hold_after_tick;
}

int execute(const Options& o, RunControlClient& client, beft::control_tool::ArbiterLink& link) {
  // The arbiter's state first: it listens, and a step counts from its tick.
  if (!link.waitUntil([&] { return client.lastState() || link.ended(); }, o.timeout_s)) {
    std::fprintf(stderr,
                 "beft-control: error: no RUN_CONTROL_STATE from an arbiter within %.1f s on %s: is a run going on "
                 "there (and is it the run meant: --run-id)?\n",
                 o.timeout_s, o.lcm_url.c_str());
    return 1;
  }
  if (link.ended()) return sayEnded(*link.ended(), false);
  if (o.action == Action::Status) {
    printState(*client.lastState());
    return 0;
  }
  const int64_t tick = client.lastState()->tick;
  if (o.action == Action::Pause) client.request(run_control_t::MODE_PAUSE, 0);
  if (o.action == Action::Run) client.request(run_control_t::MODE_RUN, 0);
  if (o.action == Action::Step) client.request(run_control_t::MODE_STEP, o.until >= 0 ? o.until : tick + o.ticks);
  if (!link.waitUntil([&] { return client.acknowledged() || link.ended(); }, o.timeout_s) || link.publishFailed()) {
    std::fprintf(stderr, "beft-control: error: the arbiter did not answer the request within %.1f s (sent again every "
                 "%.1f s)\n", o.timeout_s, RunControlClient::kResendInterval_us * 1e-6);
    return 1;
  }
  const run_control_t wanted = *client.desired();
  const bool waits = o.action != Action::Run && !o.no_wait;
  if (waits && !link.waitUntil([&] { return holdsAsAsked(*client.lastState(), wanted) || link.ended(); }, o.timeout_s)) {
    printState(*client.lastState());
    std::fprintf(stderr, "beft-control: the arbiter took the request, but the run did not hold within %.1f s\n",
                 o.timeout_s);
    return 3;
  }
  if (link.ended() && waits) return sayEnded(*link.ended(), true);
  printState(*client.lastState());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  lcm::LCM lcm(o.lcm_url);
  if (!lcm.good()) {
    std::fprintf(stderr, "beft-control: error: cannot open LCM at %s\n", o.lcm_url.c_str());
    return 1;
  }
  std::unique_ptr<beft::transport::PublisherScope> publishing;
  try {
    publishing = beft::transport::attachPublisher(lcm, o.lcm_url, "beft-control");
    if (!o.run_id.empty()) beft::wire::setRunId(beft::wire::parseRunId(o.run_id));
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "beft-control: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beft-control: error: cannot publish on %s: %s\n", o.lcm_url.c_str(), e.what());
    return 1;
  }
  const std::string why = o.run_id.empty() ? beft::wire::adoptTheRunHeard(lcm, std::min(o.timeout_s, 2.0)) : "";
  if (!why.empty()) {
    std::fprintf(stderr, "beft-control: error: %s\n", why.c_str());
    return 2;
  }
  // Numbered from the wall clock: above whatever an earlier beft-control of this origin sent.
  RunControlClient client(o.origin, beft::wallMicros());
  beft::control_tool::ArbiterLink link(lcm, client);
  return execute(o, client, link);
}

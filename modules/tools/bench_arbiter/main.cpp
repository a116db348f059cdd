// beft-bench-arbiter: what the arbiter costs per tick (`./beft bench arbiter`).
//  1. the core alone, experts answering at once in-process: pure scheduling cost;
//  2. the whole loop over LCM UDP with an instant responder thread standing in
//     for every expert: the lockstep round trip FIRE -> DONE per tick.
#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <optional>
#include <deque>
#include <thread>

#include "lib/common/command_line.hpp"
#include "services/arbiter/arbiter_core.hpp"
#include "lib/common/channels.hpp"
#include "services/arbiter/lcm_arbiter.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/common/log.hpp"
#include "lib/petri/pnml_reader.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/run_identity.hpp"

namespace {

using namespace beft::arbiter;

// Collects FIREs; the driver answers them with DONE at once.
class InstantExperts : public ArbiterOutput {
 public:
  void sendFire(const beft::fire_t& fire) override { fires.push_back(fire); }
  void sendMarking(const beft::marking_t&) override { ++markings; }
  void sendRunStatus(const beft::run_status_t&) override {}
  void firingEnded(const FiringRecord&) override {}
  std::deque<beft::fire_t> fires;
  int64_t markings = 0;
};

beft::done_t doneFor(const beft::fire_t& fire) {
  beft::done_t done{};
  done.utime = fire.utime;
  done.expert = fire.expert;
  done.tick = fire.tick;
  done.firing_id = fire.firing_id;
  done.outcome = beft::done_t::OUTCOME_OK;
  done.duration = 0.0;
  return done;
}

beft::heartbeat_t heartbeatFor(const std::string& expert) {
  beft::heartbeat_t beat{};
  beat.process = expert;
  beat.pid = static_cast<int32_t>(getpid());
  beat.host = "bench";
  beat.last_firing_id = -1;
  beat.state = "idle";
  return beat;
}

void benchCore(const Net& net, int64_t ticks) {
  SteadyClock clock;
  InstantExperts experts;
  ArbiterConfig config;
  config.max_ticks = ticks;
  config.final_status_repeats = 1;
  ArbiterCore core(net, config, clock, experts);
  for (const auto& name : net.experts()) core.onHeartbeat(heartbeatFor(name));
  const auto start = std::chrono::steady_clock::now();
  core.start();
  while (!core.ended() && !experts.fires.empty()) {
    const beft::fire_t fire = experts.fires.front();
    experts.fires.pop_front();
    core.onDone(doneFor(fire));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto& s = core.stats();
  std::printf("core only:   %lld ticks, %lld firings, %lld MARKING steps in %.3f s: %.2f us per tick, "
              "%.3f us per firing (%s)\n",
              static_cast<long long>(s.ticks_completed), static_cast<long long>(s.firings_done),
              static_cast<long long>(experts.markings), seconds, seconds * 1e6 / static_cast<double>(ticks),
              seconds * 1e6 / static_cast<double>(std::max<int64_t>(1, s.firings_done)),
              runStateName(core.state()));
}

// Stands in for every expert of the net on an LCM instance of its own.
void respond(lcm::LCM& lcm, const std::vector<std::string>& experts, std::atomic<bool>& stop) {
  struct Handler {
    lcm::LCM* lcm;
    bool ended = false;
    // Raw bytes through the message guard, as every program takes them.
    static void onFire(const lcm::ReceiveBuffer* buffer, const std::string& channel, Handler* self) {
      beft::fire_t fire{};
      if (!beft::wire::decodeFrom(channel, buffer->data, buffer->data_size, fire)) return;
      const beft::done_t done = doneFor(fire);
      beft::transport::publish(*self->lcm, beft::wire::runChannel(beft::channels::kDone), done);
    }
    static void onStatus(const lcm::ReceiveBuffer* buffer, const std::string& channel, Handler* self) {
      beft::run_status_t status{};
      if (!beft::wire::decodeFrom(channel, buffer->data, buffer->data_size, status)) return;
      self->ended = status.state == beft::run_status_t::STATE_FINISHED ||
                    status.state == beft::run_status_t::STATE_FAILED;
    }
  } handler{&lcm};
  lcm.subscribeFunction(beft::wire::runChannel(beft::channels::kFire), &Handler::onFire, &handler)
      ->setQueueCapacity(10000);
  lcm.subscribeFunction(beft::wire::runChannel(beft::channels::kRunStatus), &Handler::onStatus, &handler);
  auto next_heartbeat = std::chrono::steady_clock::now();
  while (!stop && !handler.ended) {
    if (std::chrono::steady_clock::now() >= next_heartbeat) {
      for (const auto& name : experts) {
        const beft::heartbeat_t beat = heartbeatFor(name);
        beft::transport::publish(lcm, beft::wire::runChannel(beft::channels::kHeartbeat), beat);
      }
      next_heartbeat += std::chrono::milliseconds(200);
    }
    lcm.handleTimeout(20);
  }
}

void benchLcm(const Net& net, int64_t ticks, const std::string& url) {
  lcm::LCM lcm(url);
  if (!lcm.good()) {
    std::printf("over LCM:    cannot open %s\n", url.c_str());
    return;
  }
  const auto publishing = beft::transport::attachPublisher(lcm, url, "bench-arbiter");
  lcm::LCM experts_lcm(url);
  const auto experts_publishing = beft::transport::attachPublisher(experts_lcm, url, "bench-arbiter-experts");
  std::atomic<bool> stop{false};
  std::thread responder(respond, std::ref(experts_lcm), net.experts(), std::ref(stop));
  SteadyClock clock;
  ArbiterOutlets outlets;
  LcmArbiterOutput output(lcm, outlets, nullptr);
  ArbiterConfig config;
  config.max_ticks = ticks;
  ArbiterCore core(net, config, clock, output);
  ArbiterInbox inbox;
  ArbiterEventQueue events(lcm, url, inbox);
  const auto start = std::chrono::steady_clock::now();
  runArbiterLoop(events, core, clock);
  stop = true;
  responder.join();
  // The final status is repeated over a few periods: leave that out of the figure.
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() -
                         (config.final_status_repeats - 1) * config.final_status_period_s;
  const auto& s = core.stats();
  std::printf("over LCM:    %lld ticks, %lld firings in %.3f s (start-up wait included): %.1f us per tick, "
              "%.1f ticks/s; FIRE re-sends %lld, duplicate DONEs %lld (%s)\n",
              static_cast<long long>(s.ticks_completed), static_cast<long long>(s.firings_done), seconds,
              seconds * 1e6 / static_cast<double>(ticks), static_cast<double>(ticks) / seconds,
              static_cast<long long>(s.fire_resends), static_cast<long long>(s.duplicate_dones),
              runStateName(core.state()));
}

struct Options {
  std::string net_path = std::string(BEFT_SOURCE_DIR) + "/scenarios/nets/default.pnml";
  int64_t core_ticks = 100000;
  int64_t lcm_ticks = 2000;
  std::string lcm_url = beft::lcmUrlForPort(17000 + static_cast<int>(getpid() % 20000));
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app("Measures the arbiter's cost per tick: the core alone with instant in-process experts, "
               "then the LCM loop with an instant responder thread for every expert.",
               "beft-bench-arbiter");
  app.add_option("--net", o.net_path, "PNML net")->capture_default_str();
  app.add_option("--core-ticks", o.core_ticks, "ticks for the core-only run")->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--lcm-ticks", o.lcm_ticks, "ticks for the LCM run")->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--lcm-url", o.lcm_url, "LCM URL of the LCM run (default: a port of its own)")
      ->capture_default_str();
  return beft::parseCommandLine(app, argc, argv);
}

int bench(const Options& o) {
  beft::log::setProcessName("bench-arbiter");
  beft::log::setLevel(beft::log::Level::Warn);
  Net net;
  try {
    net = readPnmlFile(o.net_path);
  } catch (const NetError& e) {
    for (const auto& problem : e.problems()) std::fprintf(stderr, "%s\n", problem.c_str());
    return 2;
  }
  std::printf("net %s: %zu experts, %zu transitions\n", o.net_path.c_str(), net.experts().size(),
              net.transitions.size());
  benchCore(net, o.core_ticks);
  try {
    benchLcm(net, o.lcm_ticks, o.lcm_url);
  } catch (const std::exception& e) {
    std::printf("over LCM:    %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return bench(options);
}

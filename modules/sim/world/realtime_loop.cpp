#include "sim/world/realtime_loop.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <memory>
#include <thread>

#include <lcm/lcm-cpp.hpp>

#include "lib/common/channels.hpp"
#include "lib/common/log.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::world {

namespace {

std::atomic<bool> g_stop{false};
void onSignal(int) { g_stop = true; }

class LcmPublisher : public beft::expert::Output {
 public:
  explicit LcmPublisher(lcm::LCM& lcm) : lcm_(lcm) {}
  void publishEncoded(const std::string& channel, const std::vector<uint8_t>& bytes) override {
    if (transport::publishEncoded(lcm_, wire::runChannel(channel), bytes.data(), bytes.size()) != 0) {
      log::warn("could not publish on ", channel, " (", bytes.size(), " bytes)");
    }
  }

 private:
  lcm::LCM& lcm_;
};

class CommandListener {
 public:
  explicit CommandListener(WorldExpert& world) : world_(world) {}
  void onCommand(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    try {
      const std::string plain(wire::splitRunChannel(channel).base);
      world_.onMessage(plain, buffer->data, static_cast<int>(buffer->data_size));  // refusals: counted by the guard
    } catch (const std::exception& e) {
      log::error("message on ", channel, " raised: ", e.what());
    }
  }

 private:
  WorldExpert& world_;
};

}  // namespace

int runRealtime(WorldExpert& world, const RealtimeOptions& options) {
  WorldSimulation* simulation = world.simulation();
  if (!simulation) {
    log::error("no scenario loaded");
    return 2;
  }
  if (!(options.rate_hz > 0) || !std::isfinite(options.rate_hz)) {
    log::error("--realtime rate must be a positive number of ticks per second");
    return 2;
  }
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  lcm::LCM lcm(options.lcm_url);
  if (!lcm.good()) {
    log::error("cannot open LCM at ", options.lcm_url);
    return 1;
  }
  std::unique_ptr<transport::PublisherScope> publishing;
  try {
    publishing = transport::attachPublisher(lcm, options.lcm_url, world.name());
  } catch (const std::exception& e) {
    log::error("cannot publish on ", options.lcm_url, ": ", e.what());
    return 1;
  }
  CommandListener listener(world);
  lcm.subscribe(wire::runChannel(channels::kRobotCommand), &CommandListener::onCommand, &listener)
      ->setQueueCapacity(1000);
  LcmPublisher publisher(lcm);

  const scenario::Scenario& scenario = simulation->scenario();
  const int64_t last_tick = options.last_tick >= 0
                                ? options.last_tick
                                : static_cast<int64_t>(std::floor(scenario.duration / scenario.dt + 1e-9));
  log::info("free-running at ", options.rate_hz, " ticks/s on ", options.lcm_url, " until tick ", last_tick);

  using Clock = std::chrono::steady_clock;
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / options.rate_hz));
  auto deadline = Clock::now();
  int64_t late_ticks = 0;
  for (int64_t tick = 0; tick <= last_tick && !g_stop; ++tick) {
    beft::expert::Firing firing;
    firing.expert = world.name();
    firing.tick = tick;
    firing.utime = std::llround(tick * scenario.dt * 1e6);
    firing.firing_id = tick + 1;
    const beft::expert::Outcome outcome = world.fire(firing, publisher);
    if (!outcome.ok) log::warn("tick ", tick, ": ", outcome.message);
    // Take commands until the next tick is due.
    deadline += period;
    if (Clock::now() > deadline) {
      if (++late_ticks == 1) log::warn("cannot keep up with ", options.rate_hz, " ticks/s; running as fast as it can");
      deadline = Clock::now();
    }
    while (!g_stop) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) {
        while (lcm.handleTimeout(0) > 0) {
        }
        break;
      }
      if (lcm.handleTimeout(static_cast<int>(std::min<int64_t>(left, 100))) < 0) {
        log::error("LCM receive failed; stopping");
        return 1;
      }
    }
  }
  log::info(g_stop ? "stopped by signal" : "reached the last tick", " at tick ", simulation->tick());
  return 0;
}

}  // namespace beft::world

// beft-world: the simulated world process.
//   beft-world --scenario scenarios/yard.xml               lockstep: steps when the arbiter fires "world"
//   beft-world --scenario scenarios/yard.xml --realtime 10 free-running at 10 ticks per second
#include <CLI/CLI.hpp>

#include "sim/world/realtime_loop.hpp"
#include "lib/expert/run_expert.hpp"
#include "sim/world/world_expert.hpp"

int main(int argc, char** argv) {
  beft::world::WorldExpert world;
  beft::world::RealtimeOptions realtime;
  const auto add_options = [&](CLI::App& app) {
    app.add_option("--scenario", world.scenario_path, "scenario XML file (required)");
    app.add_option_function<uint64_t>(
        "--seed", [&world](const uint64_t& seed) { world.seed = seed; },
        "random seed (default: the scenario's seed); fixes the depth noise");
    app.add_option("--realtime", realtime.rate_hz,
                   "free-run at RATE_HZ ticks per wall-clock second without an arbiter, until the scenario's end")
        ->check(CLI::PositiveNumber);
    app.add_option("--ticks", realtime.last_tick, "with --realtime: stop after this tick (default: the scenario's end)")
        ->check(CLI::NonNegativeNumber);
  };
  const auto run_free = [&](const std::string& lcm_url) -> std::optional<int> {
    if (realtime.rate_hz <= 0) return std::nullopt;
    realtime.lcm_url = lcm_url;
    return beft::world::runRealtime(world, realtime);
  };
  return beft::expert::runExpertMain(argc, argv, world, add_options, run_free);
}

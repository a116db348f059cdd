// beft-world: the simulated world process.
//   beft-world --scenario scenarios/yard.xml               lockstep: steps when the arbiter fires "world"
//   beft-world --scenario scenarios/yard.xml --realtime 10 free-running at 10 ticks per second
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "lcm_url.hpp"
#include "log.hpp"
#include "realtime_loop.hpp"
#include "run_expert.hpp"
#include "world_expert.hpp"

namespace {

constexpr const char* kRealtimeHelp =
    "free-run at RATE_HZ ticks per wall-clock second without an arbiter, until the scenario's end "
    "(then only --scenario, --seed, --lcm-url, --param and --ticks apply)";

bool hasRealtimeFlag(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--realtime") == 0 || std::strncmp(argv[i], "--realtime=", 11) == 0) return true;
  }
  return false;
}

void addWorldOptions(CLI::App& app, beft::world::WorldExpert& world) {
  app.add_option("--scenario", world.scenario_path, "scenario XML file (required)");
  app.add_option_function<uint64_t>(
      "--seed", [&world](const uint64_t& seed) { world.seed = seed; },
      "random seed (default: the scenario's seed); fixes the depth noise");
}

int runFreeRunning(int argc, char** argv, beft::world::WorldExpert& world) {
  beft::world::RealtimeOptions options;
  options.lcm_url = beft::defaultLcmUrl();
  std::vector<std::string> parameter_args;
  CLI::App app(world.description() + "\n\nFree-running mode: " + kRealtimeHelp + ".", "beft-world");
  addWorldOptions(app, world);
  app.add_option("--realtime", options.rate_hz, "ticks per wall-clock second")->required()->check(
      CLI::PositiveNumber);
  app.add_option("--ticks", options.last_tick, "stop after this tick (default: the scenario's end)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--lcm-url", options.lcm_url, "LCM URL (env BEFT_LCM_URL)")->capture_default_str();
  app.add_option("--param", parameter_args, "parameter NAME=VALUE (repeatable): depth_noise, render_threads");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  beft::log::setProcessName(world.name());
  std::set<std::string> known;
  for (const auto& row : world.parameterHelp()) known.insert(row.at(0));
  beft::expert::Parameters parameters;
  for (const std::string& arg : parameter_args) {
    const auto eq = arg.find('=');
    if (eq == std::string::npos || eq == 0 || !known.count(arg.substr(0, eq))) {
      beft::log::error("--param '", arg, "' is not NAME=VALUE with a known NAME (known: depth_noise, render_threads)");
      return 2;
    }
    parameters.set(arg.substr(0, eq), arg.substr(eq + 1));
  }
  try {
    world.onStartUp(parameters);
  } catch (const std::exception& e) {
    beft::log::error("start-up failed: ", e.what());
    return 2;
  }
  return beft::world::runRealtime(world, options);
}

}  // namespace

int main(int argc, char** argv) {
  beft::world::WorldExpert world;
  if (hasRealtimeFlag(argc, argv)) return runFreeRunning(argc, argv, world);
  return beft::expert::runExpertMain(argc, argv, world, [&world](CLI::App& app) {
    addWorldOptions(app, world);
    // Handled before this parser runs; listed here for --help.
    app.add_option("--realtime")->description(kRealtimeHelp)->type_name("RATE_HZ");
  });
}

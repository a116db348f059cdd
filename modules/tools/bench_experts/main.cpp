// beft-bench-experts: how long each expert takes per tick on a scenario. The
// world runs in the same process (no LCM), the robot turns in place (and
// optionally drives) so the views change, and the six experts fire every tick
// in the default schedule. Prints per-expert fire times and message sizes.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <optional>

#include "lib/common/command_line.hpp"
#include "lib/common/channels.hpp"
#include "tools/bench_experts/expert_chain.hpp"
#include "lib/camera/frame_compressor.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "sim/world/world_simulation.hpp"

namespace {

struct Summary {
  double mean = 0, median = 0, p95 = 0, max = 0;
};

Summary summarise(std::vector<double> seconds) {
  Summary s;
  if (seconds.empty()) return s;
  std::sort(seconds.begin(), seconds.end());
  s.mean = std::accumulate(seconds.begin(), seconds.end(), 0.0) / seconds.size();
  s.median = seconds[seconds.size() / 2];
  s.p95 = seconds[std::min(seconds.size() - 1, static_cast<std::size_t>(0.95 * seconds.size()))];
  s.max = seconds.back();
  return s;
}

void printRow(const std::string& name, const Summary& s) {
  std::printf("  %-16s %9.3f %9.3f %9.3f %9.3f\n", name.c_str(), 1e3 * s.mean, 1e3 * s.median, 1e3 * s.p95,
              1e3 * s.max);
}

struct Options {
  std::string scenario_path;
  int ticks = 300;
  double turn_rate = 20, speed = 0;  // platform motion while running [deg/s], [m/s]
  std::map<std::string, std::map<std::string, std::string>> parameters;  // by expert
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  std::vector<std::string> parameter_args;
  CLI::App app(
      "Times the expert hierarchy (geometry, vision, audio, visual_labels, acoustic_labels, fusion) per "
      "tick on a scenario, in one process without LCM: the world steps, renders the camera, and every "
      "expert fires once per tick in the default schedule. Prints mean / median / 95th percentile / max "
      "CPU time of fire() per expert (CPU time: a busy machine does not inflate it), the world's step "
      "for comparison, and the message sizes.",
      "beft-bench-experts");
  app.add_option("--scenario", o.scenario_path, "scenario XML file")->required();
  app.add_option("--ticks", o.ticks, "ticks to run")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--turn-rate", o.turn_rate, "platform turn rate while running [deg/s]")->capture_default_str();
  app.add_option("--speed", o.speed, "platform forward speed while running [m/s]")->capture_default_str();
  app.add_option("--param", parameter_args, "expert parameter EXPERT.NAME=VALUE, e.g. vision.free_space_stride=1");
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  for (const auto& arg : parameter_args) {
    const auto dot = arg.find('.'), eq = arg.find('=');
    if (dot == std::string::npos || eq == std::string::npos || dot > eq) {
      std::fprintf(stderr, "beft-bench-experts: --param '%s' is not EXPERT.NAME=VALUE\n", arg.c_str());
      return 2;
    }
    o.parameters[arg.substr(0, dot)][arg.substr(dot + 1, eq - dot - 1)] = arg.substr(eq + 1);
  }
  return std::nullopt;
}

struct Timings {
  std::vector<double> world_seconds, chain_seconds;
  std::size_t failures = 0;
};

// The world steps (turning and driving), then the experts fire once per tick.
Timings timeTicks(const Options& o, beft::world::WorldSimulation& world, beft::bench::ExpertChain& chain) {
  Timings t;
  beft::camera::CameraMessages frames, packed;
  beft::camera::FrameCompressor compressor;
  for (int k = 0; k < o.ticks; ++k) {
    const double world_start = beft::bench::threadCpuSeconds();
    if (k > 0) {
      beft::robot_command_t command{};
      command.mode = beft::robot_command_t::MODE_VELOCITY;
      const double heading = world.robotState().yaw * M_PI / 180.0;
      command.vx = o.speed * std::cos(heading);
      command.vy = o.speed * std::sin(heading);
      command.yaw_rate = o.turn_rate;
      command.source = "bench";
      world.submitCommand(command);
      world.step();
    }
    const auto scene = world.groundTruth();
    const auto robot = world.robotState();
    world.cameraMessages(frames);
    compressor.compress(frames, packed);  // as the world publishes them
    const double chain_start = beft::bench::threadCpuSeconds();
    t.world_seconds.push_back(chain_start - world_start);
    const auto problems = chain.runTick(scene, robot, packed.depth, packed.instance);
    t.chain_seconds.push_back(beft::bench::threadCpuSeconds() - chain_start);
    for (const auto& p : problems)
      if (t.failures++ < 5) std::fprintf(stderr, "tick %d: %s\n", k, p.c_str());
  }
  return t;
}

void printTimings(const Options& o, const beft::scenario::Scenario& scenario, const beft::bench::ExpertChain& chain,
                  const Timings& t) {
  std::printf("scenario %s: %zu objects, %d ticks, camera %dx%d, turn %.0f deg/s, speed %.2f m/s\n",
              scenario.name.c_str(), scenario.objects.size(), o.ticks, scenario.robot.camera.width,
              scenario.robot.camera.height, o.turn_rate, o.speed);
  std::printf("  %-16s %9s %9s %9s %9s   [ms of CPU per tick]\n", "expert", "mean", "median", "p95", "max");
  for (const auto& name : chain.expertNames()) printRow(name, summarise(chain.fireSeconds().at(name)));
  printRow("all six", summarise(t.chain_seconds));
  printRow("(world step)", summarise(t.world_seconds));
  const double mean_chain = summarise(t.chain_seconds).mean;
  std::printf("  expert hierarchy alone: %.0f ticks/s (%.0fx real time at dt = %.2f s)\n", 1.0 / mean_chain,
              1.0 / mean_chain * scenario.dt, scenario.dt);
  std::printf("  message sizes [bytes]: OBSTACLE_MAP %zu (last keyframe), OBSTACLE_MAP_CHANGES %zu, VISION %zu, LABELS_VISUAL %zu, HYPOTHESES %zu (last keyframe), "
              "HYPOTHESIS_CHANGES %zu\n",
              chain.latestSize(beft::channels::kObstacleMap), chain.latestSize(beft::channels::kObstacleMapChanges),
              chain.latestSize(beft::channels::kVision),
              chain.latestSize(beft::channels::kLabelsVisual), chain.latestSize(beft::channels::kHypotheses),
              chain.latestSize(beft::channels::kHypothesisChanges));
  if (t.failures > 0) std::printf("  %zu firing failures (first ones above)\n", t.failures);
}

int bench(const Options& o) {
  try {
    const auto scenario = beft::scenario::loadScenario(o.scenario_path);
    beft::world::WorldSimulation world(scenario, beft::world::WorldOptions{scenario.seed, 0});
    beft::bench::ExpertChain chain(o.parameters);
    const Timings t = timeTicks(o, world, chain);
    printTimings(o, scenario, chain, t);
    return t.failures > 0 ? 1 : 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beft-bench-experts: %s\n", e.what());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return bench(options);
}

// beft-snapshot: runs the world in-process (no LCM) to a tick and writes the
// camera frame and a top-down view of the scene as PNG files.
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <opencv2/imgcodecs.hpp>

#include "lib/common/command_line.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/common/log.hpp"
#include "tools/snapshot/snapshot_images.hpp"
#include "sim/world/world_simulation.hpp"

namespace {

bool writePng(const std::filesystem::path& path, const cv::Mat& image) {
  try {
    if (cv::imwrite(path.string(), image)) {
      std::printf("wrote %s (%dx%d)\n", path.string().c_str(), image.cols, image.rows);
      return true;
    }
  } catch (const cv::Exception& e) {
    beft::log::error("cannot write ", path.string(), ": ", e.what());
    return false;
  }
  beft::log::error("cannot write ", path.string());
  return false;
}

struct Options {
  std::string scenario_path, out_dir;
  std::optional<int64_t> tick;
  std::optional<double> time;
  std::optional<uint64_t> seed;
  std::vector<double> goto_pose, head;
  int zoom = 4;
  double pixels_per_metre = 0;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Runs the world in-process (no LCM) from tick 0 to the given tick or time and writes what it sees: "
      "camera_color.png, camera_depth.png (colour-mapped, near = red), camera_instance.png (each object in its "
      "own colour with its id) and topdown.png (the world from above: objects coloured by category with their "
      "ids, sound sources, paths, the robot with its heading and the camera's field of view). Without "
      "--goto/--head the robot stays where the scenario puts it.",
      "beft-snapshot");
  app.add_option("--scenario", o.scenario_path, "scenario XML file")->required();
  auto* tick_option = app.add_option("--tick", o.tick, "tick to stop at (default 0)")->check(CLI::NonNegativeNumber);
  app.add_option("--time", o.time, "simulated time to stop at [s] (the first tick at or after it)")
      ->check(CLI::NonNegativeNumber)
      ->excludes(tick_option);
  app.add_option("--out", o.out_dir, "folder for the PNG files (created if missing)")->required();
  app.add_option("--seed", o.seed, "random seed (default: the scenario's)");
  app.add_option("--goto", o.goto_pose, "drive the robot from tick 0 towards X,Y,YAW")->expected(3)->delimiter(',');
  app.add_option("--head", o.head, "turn the head from tick 0 to YAW,PITCH [deg]")->expected(2)->delimiter(',');
  app.add_option("--zoom", o.zoom, "camera images: pixels per camera pixel")->capture_default_str()->check(
      CLI::Range(1, 16));
  app.add_option("--scale", o.pixels_per_metre, "top-down view: pixels per metre (default: about 1200 px wide)");
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

// The --goto and --head command, from tick 0; false when the world refuses it.
bool commandRobot(const Options& o, beft::world::WorldSimulation& world) {
  beft::robot_command_t command{};
  command.mode = beft::robot_command_t::MODE_STOP;
  command.source = "beft-snapshot";
  if (o.goto_pose.size() == 3) {
    command.mode = beft::robot_command_t::MODE_GOTO;
    command.goal_x = o.goto_pose[0];
    command.goal_y = o.goto_pose[1];
    command.goal_yaw = o.goto_pose[2];
  }
  if (o.head.size() == 2) {
    command.set_head = true;
    command.head_yaw = o.head[0];
    command.head_pitch = o.head[1];
  }
  if (o.goto_pose.size() == 3 || o.head.size() == 2) {
    const beft::world::CommandCheck check = world.submitCommand(command);
    if (!check.command) {
      beft::log::error("command refused: ", check.refusal);
      return false;
    }
    if (!check.adjustments.empty()) beft::log::info("command adjusted: ", check.adjustments);
  }

  return true;
}

// The four pictures; false when one cannot be written.
bool writeImages(const Options& o, beft::world::WorldSimulation& world) {
  std::error_code error;
  std::filesystem::create_directories(o.out_dir, error);
  if (error) {
    beft::log::error("cannot create ", o.out_dir, ": ", error.message());
    return false;
  }
  beft::camera::RenderedFrame frame;
  world.renderCamera(frame);
  const std::filesystem::path dir(o.out_dir);
  bool ok = writePng(dir / "camera_color.png", beft::snapshot::colorImage(frame, o.zoom));
  ok = writePng(dir / "camera_depth.png", beft::snapshot::depthImage(frame, o.zoom)) && ok;
  ok = writePng(dir / "camera_instance.png", beft::snapshot::instanceImage(frame, world, o.zoom)) && ok;
  ok = writePng(dir / "topdown.png", beft::snapshot::topDownImage(world, o.pixels_per_metre)) && ok;
  return ok;
}

int snapshot(const Options& o) {
  beft::scenario::Scenario scenario;
  try {
    scenario = beft::scenario::loadScenario(o.scenario_path);
  } catch (const beft::scenario::ScenarioError& e) {
    beft::log::error(e.what());
    return 2;
  }
  beft::world::WorldOptions options;
  options.seed = o.seed.value_or(scenario.seed);
  beft::world::WorldSimulation world(scenario, options);
  for (const std::string& note : world.notes()) beft::log::info(note);
  if (!commandRobot(o, world)) return 2;
  const int64_t target = o.time ? beft::world::eventTick(*o.time, scenario.dt) : o.tick.value_or(0);
  while (world.tick() < target) {
    world.step();
    for (const std::string& note : world.notes()) beft::log::info(note);
  }
  const bool ok = writeImages(o, world);
  std::printf("tick %lld (t = %.2f s): robot at (%.2f, %.2f) yaw %.1f deg, head %.1f/%.1f deg\n",
              static_cast<long long>(world.tick()), world.time(), world.robot().x(), world.robot().y(),
              world.robot().yaw(), world.robot().headYaw(), world.robot().headPitch());
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  beft::log::setProcessName("snapshot");
  return snapshot(options);
}

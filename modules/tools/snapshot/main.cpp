// beft-snapshot: runs the world in-process (no LCM) to a tick and writes the
// camera frame and a top-down view of the scene as PNG files.
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <opencv2/imgcodecs.hpp>

#include "load_scenario.hpp"
#include "log.hpp"
#include "snapshot_images.hpp"
#include "world_simulation.hpp"

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

}  // namespace

int main(int argc, char** argv) {
  std::string scenario_path, out_dir;
  std::optional<int64_t> tick;
  std::optional<double> time;
  std::optional<uint64_t> seed;
  std::vector<double> goto_pose, head;
  int zoom = 4;
  double pixels_per_metre = 0;
  CLI::App app(
      "Runs the world in-process (no LCM) from tick 0 to the given tick or time and writes what it sees: "
      "camera_color.png, camera_depth.png (colour-mapped, near = red), camera_instance.png (each object in its "
      "own colour with its id) and topdown.png (the world from above: objects coloured by category with their "
      "ids, sound sources, paths, the robot with its heading and the camera's field of view). Without "
      "--goto/--head the robot stays where the scenario puts it.",
      "beft-snapshot");
  app.add_option("--scenario", scenario_path, "scenario XML file")->required();
  auto* tick_option = app.add_option("--tick", tick, "tick to stop at (default 0)")->check(CLI::NonNegativeNumber);
  app.add_option("--time", time, "simulated time to stop at [s] (the first tick at or after it)")
      ->check(CLI::NonNegativeNumber)
      ->excludes(tick_option);
  app.add_option("--out", out_dir, "folder for the PNG files (created if missing)")->required();
  app.add_option("--seed", seed, "random seed (default: the scenario's)");
  app.add_option("--goto", goto_pose, "drive the robot from tick 0 towards X,Y,YAW")->expected(3)->delimiter(',');
  app.add_option("--head", head, "turn the head from tick 0 to YAW,PITCH [deg]")->expected(2)->delimiter(',');
  app.add_option("--zoom", zoom, "camera images: pixels per camera pixel")->capture_default_str()->check(
      CLI::Range(1, 16));
  app.add_option("--scale", pixels_per_metre, "top-down view: pixels per metre (default: about 1200 px wide)");
  CLI11_PARSE(app, argc, argv);
  beft::log::setProcessName("snapshot");

  beft::scenario::Scenario scenario;
  try {
    scenario = beft::scenario::loadScenario(scenario_path);
  } catch (const beft::scenario::ScenarioError& e) {
    beft::log::error(e.what());
    return 2;
  }
  beft::world::WorldOptions options;
  options.seed = seed.value_or(scenario.seed);
  beft::world::WorldSimulation world(scenario, options);
  for (const std::string& note : world.notes()) beft::log::info(note);

  beft::robot_command_t command{};
  command.mode = beft::robot_command_t::MODE_STOP;
  command.source = "beft-snapshot";
  if (goto_pose.size() == 3) {
    command.mode = beft::robot_command_t::MODE_GOTO;
    command.goal_x = goto_pose[0];
    command.goal_y = goto_pose[1];
    command.goal_yaw = goto_pose[2];
  }
  if (head.size() == 2) {
    command.set_head = true;
    command.head_yaw = head[0];
    command.head_pitch = head[1];
  }
  if (goto_pose.size() == 3 || head.size() == 2) {
    const beft::world::CommandCheck check = world.submitCommand(command);
    if (!check.command) {
      beft::log::error("command refused: ", check.refusal);
      return 2;
    }
    if (!check.adjustments.empty()) beft::log::info("command adjusted: ", check.adjustments);
  }

  const int64_t target = time ? beft::world::eventTick(*time, scenario.dt) : tick.value_or(0);
  while (world.tick() < target) {
    world.step();
    for (const std::string& note : world.notes()) beft::log::info(note);
  }

  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) {
    beft::log::error("cannot create ", out_dir, ": ", error.message());
    return 1;
  }
  beft::camera::RenderedFrame frame;
  world.renderCamera(frame);
  const std::filesystem::path dir(out_dir);
  bool ok = writePng(dir / "camera_color.png", beft::snapshot::colorImage(frame, zoom));
  ok = writePng(dir / "camera_depth.png", beft::snapshot::depthImage(frame, zoom)) && ok;
  ok = writePng(dir / "camera_instance.png", beft::snapshot::instanceImage(frame, world, zoom)) && ok;
  ok = writePng(dir / "topdown.png", beft::snapshot::topDownImage(world, pixels_per_metre)) && ok;
  std::printf("tick %lld (t = %.2f s): robot at (%.2f, %.2f) yaw %.1f deg, head %.1f/%.1f deg\n",
              static_cast<long long>(world.tick()), world.time(), world.robot().x(), world.robot().y(),
              world.robot().yaw(), world.robot().headYaw(), world.robot().headPitch());
  return ok ? 0 : 1;
}

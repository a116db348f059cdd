#include "sim/world/world_expert.hpp"

#include <cmath>
#include <stdexcept>

#include <beft/robot_command_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/common/log.hpp"

namespace beft::world {

std::string WorldExpert::description() const {
  return "The simulated world: loads a scenario, owns simulated time (tick k at t = k * dt) and, each time it "
         "is fired, applies the latest robot command, moves objects along their paths, applies due events, "
         "then publishes ground truth, robot state and the RGBD camera frame of that tick (its colour, depth "
         "and instance images losslessly compressed).";
}

void WorldExpert::declareParameters(DeclaredParameters& parameters) {
  parameters.declare("depth_noise", options_.depth_noise, 0, DeclaredParameters::kNoLimit,
                     "depth noise: standard deviation depth_noise * depth^2 [m], seeded by --seed and the tick");
  parameters.declare("render_threads", options_.render_threads, 1, 16,
                     "threads the camera renders on; the images are the same for any count");
  parameters.declare("scene_keyframe_ticks", options_.scene_keyframe_ticks, 1, 1000000,
                     "GT_OBJECTS is published when the scene changes and every this many ticks (1: every tick); "
                     "GT_VERSION says every tick which one holds");
}

void WorldExpert::onStartUp() {
  if (scenario_path.empty()) throw std::invalid_argument("--scenario FILE is required");
  WorldOptions options = options_;
  try {
    scenario_ = std::make_unique<scenario::Scenario>(scenario::loadScenario(scenario_path));
  } catch (const scenario::ScenarioError& e) {
    throw std::invalid_argument(e.what());
  }
  options.seed = seed.value_or(scenario_->seed);
  const scenario::Camera& camera = scenario_->robot.camera;
  simulation_ = std::make_unique<WorldSimulation>(*scenario_, options);
  if (static_cast<int64_t>(camera.width) * camera.height > camera::kMaxFramePixels) {
    throw std::invalid_argument("camera " + std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                                ": more than the " + std::to_string(camera::kMaxFramePixels) +
                                " pixels a reader accepts in a frame");
  }
  log::info("scenario '", scenario_->name, "' (", scenario_->objects.size(), " objects, dt ", scenario_->dt,
            " s, seed ", options.seed, ")");
  logNotes();
}

void WorldExpert::onCommand(robot_command_t&& command) {
  if (!simulation_) return;
  const CommandCheck check = simulation_->submitCommand(command);
  if (!check.command) {
    ++refused_commands_;
    if (refused_commands_ <= 20 || refused_commands_ % 1000 == 0) {
      log::warn("ignored ROBOT_CMD: ", check.refusal, " (", refused_commands_, " refused so far)");
    }
  } else if (!check.adjustments.empty() && check.adjustments != last_adjustment_logged_) {
    log::info("ROBOT_CMD adjusted: ", check.adjustments);
  }
  if (check.command) last_adjustment_logged_ = check.adjustments;
}

void WorldExpert::logNotes() {
  for (const std::string& note : simulation_->notes()) log::info(note);
}

// Compressed frames of the shipped cameras take a few kB; a big camera's may
// not fit one datagram, and a lost fragment loses the frame.
void WorldExpert::warnIfFragmented(const beft::camera_frame_t& frame) {
  if (warned_fragmented_ || frame.data.size() <= 60000) return;
  log::warn("camera frames of ", frame.data.size(), " bytes after compression (", frame.width, "x", frame.height,
            ") travel fragmented on LCM (a lost fragment loses the frame)");
  warned_fragmented_ = true;
}

void WorldExpert::publishState(beft::expert::Output& out) {
  // Render first: each publish wakes every process that reads the channel,
  // and they would take the cores from the rendering threads.
  simulation_->cameraMessages(camera_messages_);
  colour_packing_.start([this] { colour_compressor_.compress(camera_messages_.color, packed_camera_.color); });
  beft::expert::WaitOnExit colour_packed(colour_packing_);  // also when a publish throws
  frame_compressor_.compress(camera_messages_.depth, packed_camera_.depth);
  frame_compressor_.compress(camera_messages_.instance, packed_camera_.instance);
  const beft::scene_version_t version = simulation_->sceneVersion();
  if (version.scene_tick == version.tick) ground_truth_out_.publish(out, simulation_->groundTruth());
  scene_version_out_.publish(out, version);
  robot_state_out_.publish(out, simulation_->robotState());
  contact_out_.publish(out, simulation_->contact());
  depth_out_.publish(out, packed_camera_.depth);
  instance_out_.publish(out, packed_camera_.instance);
  colour_packing_.wait();
  color_out_.publish(out, packed_camera_.color);
  for (const beft::camera_frame_t* frame : {&packed_camera_.color, &packed_camera_.depth, &packed_camera_.instance})
    warnIfFragmented(*frame);
  published_any_ = true;
}

beft::expert::Outcome WorldExpert::fire(const beft::expert::Firing& firing, beft::expert::Output& out) {
  if (!simulation_) return beft::expert::Outcome::failure("no scenario loaded");
  const int64_t current = simulation_->tick();
  if (firing.tick < current) {
    return beft::expert::Outcome::failure("tick " + std::to_string(firing.tick) + " is already past (world at tick " +
                                          std::to_string(current) + ")");
  }
  if (firing.tick == current && published_any_) {
    log::info("fired again for tick ", current, ": publishing the same state again");
  } else if (firing.tick - current > 1) {
    log::warn("fired for tick ", firing.tick, " at tick ", current, ": stepping through ", firing.tick - current,
              " ticks with the command in force");
  }
  const int64_t own_utime = std::llround(firing.tick * simulation_->scenario().dt * 1e6);
  if (firing.utime != own_utime && !warned_time_mismatch_) {
    warned_time_mismatch_ = true;
    log::warn("FIRE for tick ", firing.tick, " says t = ", firing.utime * 1e-6, " s but the scenario's dt ",
              simulation_->scenario().dt, " s makes it ", own_utime * 1e-6,
              " s; publishing scenario time (is the arbiter's --dt the scenario's?)");
  }
  while (simulation_->tick() < firing.tick) {
    simulation_->step();
    logNotes();
  }
  publishState(out);
  return beft::expert::Outcome::success();
}

}  // namespace beft::world

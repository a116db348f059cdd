// The world as an expert: the arbiter fires it once per tick; each firing
// advances the simulation to the firing's tick and publishes the state there.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "lib/expert/expert.hpp"
#include "lib/camera/frame_compressor.hpp"
#include "lib/expert/helper_task.hpp"
#include "sim/world/world_simulation.hpp"

namespace beft::world {

class WorldExpert : public beft::expert::Expert {
 public:
  // Set from the command line (--scenario, --seed) before startUp.
  std::string scenario_path;
  std::optional<uint64_t> seed;  // empty: the scenario's seed

  std::string name() const override { return "world"; }
  std::string description() const override;
  // Tick 0 publishes the initial state; tick k > current steps up to k (one
  // step per tick, each with the command in force). A tick already passed
  // is refused (the world cannot go back).
  beft::expert::Outcome fire(const beft::expert::Firing& firing, beft::expert::Output& out) override;

  // For tests and the free-running mode.
  WorldSimulation* simulation() { return simulation_.get(); }
  // Publishes the current tick's messages.
  void publishState(beft::expert::Output& out);

 protected:
  void declareParameters(DeclaredParameters& parameters) override;
  // Loads the scenario (std::invalid_argument with FILE:LINE on a bad file).
  void onStartUp() override;

 private:
  void logNotes();
  void warnIfFragmented(const beft::camera_frame_t& frame);
  void onCommand(robot_command_t&& command);

  std::unique_ptr<scenario::Scenario> scenario_;
  std::unique_ptr<WorldSimulation> simulation_;
  camera::CameraMessages camera_messages_;  // as rendered
  camera::CameraMessages packed_camera_;    // as published: compressed
  camera::FrameCompressor frame_compressor_;
  // The colour frame, the longest to pack and read by no expert, is packed
  // on a helper while the others are packed and published.
  camera::FrameCompressor colour_compressor_;
  beft::expert::HelperTask colour_packing_;
  bool published_any_ = false;
  std::string last_adjustment_logged_;
  int64_t refused_commands_ = 0;
  bool warned_time_mismatch_ = false;
  bool warned_fragmented_ = false;
  WorldOptions options_;

  beft::expert::HandledInput<robot_command_t> commands_{
      *this, channels::kRobotCommand, [this](robot_command_t&& command) { onCommand(std::move(command)); }};
  beft::expert::OutputPort<scene_objects_t> ground_truth_out_{*this, channels::kGroundTruth};
  beft::expert::OutputPort<scene_version_t> scene_version_out_{*this, channels::kSceneVersion};
  beft::expert::OutputPort<robot_state_t> robot_state_out_{*this, channels::kRobotState};
  beft::expert::OutputPort<contact_t> contact_out_{*this, channels::kContact};
  beft::expert::OutputPort<camera_frame_t> color_out_{*this, channels::kCameraColor};
  beft::expert::OutputPort<camera_frame_t> depth_out_{*this, channels::kCameraDepth};
  beft::expert::OutputPort<camera_frame_t> instance_out_{*this, channels::kCameraInstance};
};

}  // namespace beft::world

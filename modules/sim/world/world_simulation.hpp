// The simulated world without any messaging: scenario state over ticks, the
// robot, and the camera. Tick k is simulated time t = k * dt.
//
// Tick 0 is the initial state (events at t = 0 applied, nothing moved). Each
// step() goes from tick k-1 to k: the robot moves with the command in force
// (against the obstacles as they were at k-1), then objects follow their
// paths to time t_k, then the events due at tick k apply in time order.
// The state is a pure function of the scenario, the seed and the commands
// submitted before each step.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <beft/robot_command_t.hpp>
#include <beft/contact_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/scene_version_t.hpp>

#include "lib/camera/camera_messages.hpp"
#include "lib/scene/ray_caster.hpp"
#include "sim/world/robot_platform.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/scene/scene_geometry.hpp"
#include "sim/world/scene_timeline.hpp"

namespace beft::world {

struct WorldOptions {
  uint64_t seed = 0;
  // Depth noise: Gaussian with standard deviation depth_noise * depth^2 [m]
  // (grows with the square of depth, like structured-light sensors); 0 = exact.
  double depth_noise = 0;
  // Threads the camera renders on: the world steps while every expert waits
  // for it, so a second core is mostly free then.
  int render_threads = 2;
  // GT_OBJECTS goes out when the scene changes and at every tick that is a
  // multiple of this (a reader that joins late or a cut log finds one soon).
  int scene_keyframe_ticks = 100;
};

class WorldSimulation {
 public:
  WorldSimulation(const scenario::Scenario& scenario, const WorldOptions& options);
  WorldSimulation(const WorldSimulation&) = delete;
  WorldSimulation& operator=(const WorldSimulation&) = delete;

  // Makes a ROBOT_CMD the command in force from the next step on, unless it is
  // refused (see robot_platform.hpp); the check says which.
  CommandCheck submitCommand(const beft::robot_command_t& command);

  // Advances one tick.
  void step();

  int64_t tick() const { return timeline_->tick(); }
  // The tick whose GT_OBJECTS holds now: the last change or keyframe
  // (scene_version_t); GT_OBJECTS is published at the ticks where it is this one.
  int64_t sceneTick() const;
  beft::scene_version_t sceneVersion() const;
  double time() const { return tick() * scenario_.dt; }
  int64_t utime() const;

  const scenario::Scenario& scenario() const { return scenario_; }
  const std::vector<scenario::Object>& objects() const { return timeline_->objects(); }
  const std::vector<std::string>& objectIds() const { return object_ids_; }
  const RobotPlatform& robot() const { return robot_; }
  const camera::SceneGeometry& geometry() const { return geometry_; }
  const WorldOptions& options() const { return options_; }

  // What happened in the last step (or at start): events applied, collisions.
  const std::vector<std::string>& notes() const { return notes_; }

  beft::scene_objects_t groundTruth() const;
  // The bumper: whether the last motion stopped at contact, and where.
  beft::contact_t contact() const;
  beft::robot_state_t robotState() const;
  camera::Camera camera() const;
  // Renders the current camera frame (with depth noise if configured).
  void renderCamera(camera::RenderedFrame& frame);
  void cameraMessages(camera::CameraMessages& messages);

 private:
  scenario::Scenario scenario_;
  WorldOptions options_;
  std::unique_ptr<SceneTimeline> timeline_;
  RobotPlatform robot_;
  camera::SceneGeometry geometry_;
  camera::RayCaster caster_;
  camera::RenderedFrame frame_;
  std::vector<std::string> object_ids_;
  std::vector<std::string> notes_;
  int contact_object_ = -2;  // obstacle of the contact in progress; -2: none
};

}  // namespace beft::world

// The simulated robot: a PR2-like omnidirectional platform (a disc of the
// scenario's radius) with a pan/tilt head, driven by ROBOT_CMD messages.
//
// - MODE_VELOCITY: world-frame (vx, vy) and yaw rate; a speed above max_speed
//   is scaled down to it (direction kept), a turn rate clamped to
//   max_turn_rate.
// - MODE_GOTO: drives straight at max_speed towards (goal_x, goal_y) and turns
//   towards goal_yaw at max_turn_rate, both independently (the base is
//   holonomic), and stops exactly there. The goal must lie inside the world.
// - MODE_STOP: the platform stands still.
// - MODE_HEAD_ONLY: the platform stands still; the head goes to the command's
//   head_yaw / head_pitch (set_head is implied).
// - set_head (any mode): the head turns towards head_yaw / head_pitch at
//   head_turn_rate; targets beyond the pan/tilt range are clamped to it. The
//   head keeps its last target until a command sets another.
// A command stays in force until the next one. A command with an unknown mode
// or a non-finite value among the fields its mode uses is refused and the one
// in force stays.
//
// Obstacles: every object with a visual (boxes and cylinders alike: persons
// block too) and the world's edges (the disc stays inside the world). A
// motion that would enter one stops at contact (found by bisection on the
// step) and counts as a collision; turning never collides (the base is a
// disc). A robot that starts overlapping an obstacle may move in any way that
// does not make the overlap deeper.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <beft/robot_command_t.hpp>

#include "lib/scenario/scenario.hpp"
#include "lib/scene/scene_geometry.hpp"

namespace beft::world {

// A checked command, ready to apply.
struct MotionCommand {
  enum class Mode { Stop, Velocity, Goto, HeadOnly };
  Mode mode = Mode::Stop;
  double vx = 0, vy = 0, yaw_rate = 0;       // [m/s], [deg/s]
  double goal_x = 0, goal_y = 0, goal_yaw = 0;  // [m], [deg]
  bool set_head = false;
  double head_yaw = 0, head_pitch = 0;       // [deg], within the head's range
  std::string description;                   // short text for robot_state_t.last_command
};

struct CommandCheck {
  std::optional<MotionCommand> command;  // empty: refused
  std::string refusal;                   // why it was refused
  std::string adjustments;               // what was clamped, or empty
};

// Validates a ROBOT_CMD message against the robot's limits and the world.
CommandCheck checkCommand(const beft::robot_command_t& message, const scenario::Robot& robot,
                          const scenario::World& world);

struct StepOutcome {
  double distance = 0;           // distance driven this step [m]
  bool collided = false;         // the motion was stopped at contact
  int blocking_object = -1;      // object index of the obstacle touched; -1 the world's edge or none
};

class RobotPlatform {
 public:
  RobotPlatform(const scenario::Robot& robot, const scenario::World& world);

  void setCommand(const MotionCommand& command) { command_ = command; }
  const MotionCommand& command() const { return command_; }

  // One step of dt seconds against the obstacles of `scene`.
  StepOutcome step(double dt, const camera::SceneGeometry& scene);

  // Distance from the disc's edge to the nearest obstacle or world edge at
  // (x, y) [m], negative when overlapping; nearest_object gets the object
  // index (-1: the world's edge). Looks no farther than `horizon` metres.
  double clearance(double x, double y, const camera::SceneGeometry& scene, int* nearest_object = nullptr,
                   double horizon = 2.0) const;

  double x() const { return x_; }
  double y() const { return y_; }
  double yaw() const { return yaw_; }             // (-180, 180] [deg]
  double headYaw() const { return head_yaw_; }    // [deg]
  double headPitch() const { return head_pitch_; }
  double vx() const { return vx_; }               // actual velocity of the last step [m/s]
  double vy() const { return vy_; }
  double yawRate() const { return yaw_rate_; }    // actual [deg/s]
  double pathLength() const { return path_length_; }
  int collisions() const { return collisions_; }
  bool collided() const { return collided_; }
  // The point of the footprint that touched, when collided(): its edge in the direction of motion.
  double contactX() const { return contact_x_; }
  double contactY() const { return contact_y_; }
  double contactHeading() const { return contact_heading_; }  // of the stopped motion [deg]
  const scenario::Robot& description() const { return robot_; }

 private:
  // Fraction of the planar move from (x, y) by (dx, dy) that stays clear.
  double clearFraction(double dx, double dy, const camera::SceneGeometry& scene, int* blocking_object) const;

  scenario::Robot robot_;
  scenario::World world_;
  MotionCommand command_;
  double x_, y_, yaw_, head_yaw_, head_pitch_;
  double head_yaw_target_, head_pitch_target_;
  double vx_ = 0, vy_ = 0, yaw_rate_ = 0;
  double path_length_ = 0;
  int collisions_ = 0;
  bool collided_ = false;
  double contact_x_ = 0, contact_y_ = 0, contact_heading_ = 0;
};

// Angle in (-180, 180] [deg].
double wrapDegrees(double angle);

}  // namespace beft::world

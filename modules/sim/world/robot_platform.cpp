#include "sim/world/robot_platform.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace beft::world {

namespace {

std::string formatFixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
  return buffer;
}

bool allFinite(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

void appendNote(std::string& notes, const std::string& note) {
  if (!notes.empty()) notes += "; ";
  notes += note;
}

// Moves value towards target by at most max_change.
double approach(double value, double target, double max_change) {
  return value + std::clamp(target - value, -max_change, max_change);
}

}  // namespace

double wrapDegrees(double angle) {
  double wrapped = std::fmod(angle, 360.0);
  if (wrapped <= -180.0) wrapped += 360.0;
  if (wrapped > 180.0) wrapped -= 360.0;
  return wrapped;
}

namespace {

// Each returns false with check.refusal set when the command must be refused.
bool checkVelocity(const beft::robot_command_t& message, const scenario::RobotLimits& limits, const std::string& from,
                   MotionCommand& command, CommandCheck& check) {
  if (!allFinite({message.vx, message.vy, message.yaw_rate})) {
    check.refusal = "velocity command" + from + " has a non-finite vx, vy or yaw_rate";
    return false;
  }
  command.mode = MotionCommand::Mode::Velocity;
  command.vx = message.vx;
  command.vy = message.vy;
  command.yaw_rate = message.yaw_rate;
  const double speed = std::hypot(message.vx, message.vy);
  if (speed > limits.max_speed) {
    command.vx *= limits.max_speed / speed;
    command.vy *= limits.max_speed / speed;
    appendNote(check.adjustments, "speed " + formatFixed(speed, 3) + " m/s limited to max_speed " +
                                      formatFixed(limits.max_speed, 3));
  }
  if (std::abs(message.yaw_rate) > limits.max_turn_rate) {
    command.yaw_rate = std::copysign(limits.max_turn_rate, message.yaw_rate);
    appendNote(check.adjustments, "yaw_rate " + formatFixed(message.yaw_rate, 1) +
                                      " deg/s limited to max_turn_rate " + formatFixed(limits.max_turn_rate, 1));
  }
  command.description = "velocity vx=" + formatFixed(command.vx, 2) + " vy=" + formatFixed(command.vy, 2) +
                        " yaw_rate=" + formatFixed(command.yaw_rate, 1);
  return true;
}

bool checkGoto(const beft::robot_command_t& message, const scenario::World& world, const std::string& from,
               MotionCommand& command, CommandCheck& check) {
  if (!allFinite({message.goal_x, message.goal_y, message.goal_yaw})) {
    check.refusal = "goto command" + from + " has a non-finite goal_x, goal_y or goal_yaw";
    return false;
  }
  if (message.goal_x < 0 || message.goal_x > world.width || message.goal_y < 0 ||
      message.goal_y > world.height) {
    check.refusal = "goto command" + from + ": goal (" + formatFixed(message.goal_x, 2) + ", " +
                    formatFixed(message.goal_y, 2) + ") is outside the world [0, " +
                    formatFixed(world.width, 2) + "] x [0, " + formatFixed(world.height, 2) + "]";
    return false;
  }
  command.mode = MotionCommand::Mode::Goto;
  command.goal_x = message.goal_x;
  command.goal_y = message.goal_y;
  command.goal_yaw = wrapDegrees(message.goal_yaw);
  command.description = "goto (" + formatFixed(command.goal_x, 2) + ", " + formatFixed(command.goal_y, 2) +
                        ") yaw " + formatFixed(command.goal_yaw, 1);
  return true;
}

bool checkHead(const beft::robot_command_t& message, const scenario::RobotLimits& limits, const std::string& from,
               MotionCommand& command, CommandCheck& check) {
  if (!allFinite({message.head_yaw, message.head_pitch})) {
    check.refusal = "command" + from + " has a non-finite head_yaw or head_pitch";
    return false;
  }
  const double yaw_limit = limits.head_yaw_range / 2, pitch_limit = limits.head_pitch_range / 2;
  command.head_yaw = std::clamp(message.head_yaw, -yaw_limit, yaw_limit);
  command.head_pitch = std::clamp(message.head_pitch, -pitch_limit, pitch_limit);
  if (command.head_yaw != message.head_yaw) {
    appendNote(check.adjustments, "head_yaw " + formatFixed(message.head_yaw, 1) + " deg limited to +/-" +
                                      formatFixed(yaw_limit, 1));
  }
  if (command.head_pitch != message.head_pitch) {
    appendNote(check.adjustments, "head_pitch " + formatFixed(message.head_pitch, 1) + " deg limited to +/-" +
                                      formatFixed(pitch_limit, 1));
  }
  command.description += ", head to (" + formatFixed(command.head_yaw, 1) + ", " +
                         formatFixed(command.head_pitch, 1) + ")";
  return true;
}

}  // namespace

CommandCheck checkCommand(const beft::robot_command_t& message, const scenario::Robot& robot,
                          const scenario::World& world) {
  CommandCheck check;
  MotionCommand command;
  const scenario::RobotLimits& limits = robot.limits;
  const std::string from = message.source.empty() ? "" : " from " + message.source;
  switch (message.mode) {
    case beft::robot_command_t::MODE_STOP:
      command.mode = MotionCommand::Mode::Stop;
      command.description = "stop";
      break;
    case beft::robot_command_t::MODE_VELOCITY:
      if (!checkVelocity(message, limits, from, command, check)) return check;
      break;
    case beft::robot_command_t::MODE_GOTO:
      if (!checkGoto(message, world, from, command, check)) return check;
      break;
    case beft::robot_command_t::MODE_HEAD_ONLY:
      command.mode = MotionCommand::Mode::HeadOnly;
      command.description = "head only";
      break;
    default:
      check.refusal = "unknown mode " + std::to_string(static_cast<int>(message.mode)) + from +
                      " (known: 0 stop, 1 velocity, 2 goto, 3 head only)";
      return check;
  }
  command.set_head = message.set_head || command.mode == MotionCommand::Mode::HeadOnly;
  if (command.set_head && !checkHead(message, limits, from, command, check)) return check;
  command.description += from;
  check.command = command;
  return check;
}

RobotPlatform::RobotPlatform(const scenario::Robot& robot, const scenario::World& world)
    : robot_(robot),
      world_(world),
      x_(robot.x),
      y_(robot.y),
      yaw_(wrapDegrees(robot.yaw)),
      head_yaw_(robot.head_yaw),
      head_pitch_(robot.head_pitch),
      head_yaw_target_(robot.head_yaw),
      head_pitch_target_(robot.head_pitch) {
  command_.description = "stop (none received)";
}

double RobotPlatform::clearance(double x, double y, const camera::SceneGeometry& scene, int* nearest_object,
                                double horizon) const {
  // World edges: the centre must stay radius away from them.
  double nearest = std::min({x, world_.width - x, y, world_.height - y});
  int nearest_index = -1;
  std::vector<int> near;
  scene.solidsNear(x, y, horizon + robot_.radius, near);
  for (int s : near) {
    const camera::Solid& solid = scene.solids()[s];
    const double distance = camera::footprintDistance(solid, x, y);
    if (distance < nearest) {
      nearest = distance;
      nearest_index = solid.object_index;
    }
  }
  if (nearest_object) *nearest_object = nearest_index;
  // Beyond the horizon nothing was looked at: report at most the horizon.
  return std::min(nearest - robot_.radius, horizon);
}

double RobotPlatform::clearFraction(double dx, double dy, const camera::SceneGeometry& scene,
                                    int* blocking_object) const {
  const double length = std::hypot(dx, dy);
  if (length == 0) return 1.0;
  // Free means clear of everything, or for a robot that starts overlapping,
  // no deeper than it already is.
  const double horizon = length + 1.0;
  const double threshold = std::min(0.0, clearance(x_, y_, scene, nullptr, horizon));
  const auto freeAt = [&](double s) {
    return clearance(x_ + s * dx, y_ + s * dy, scene, nullptr, horizon) >= threshold;
  };
  // March along the move: the clearance is a distance, so advancing by it
  // cannot pass through anything; never less than 1 cm per sample.
  constexpr double kMinAdvance = 0.01;  // [m]
  double s = 0;
  while (s < 1.0) {
    const double room = clearance(x_ + s * dx, y_ + s * dy, scene, nullptr, horizon) - threshold;
    const double s_next = std::min(1.0, s + std::max(room, kMinAdvance) / length);
    if (freeAt(s_next)) {
      s = s_next;
      continue;
    }
    // Contact lies in (s, s_next]: bisect to well under a micrometre.
    double free_s = s, blocked_s = s_next;
    for (int i = 0; i < 40 && (blocked_s - free_s) * length > 1e-7; ++i) {
      const double mid = 0.5 * (free_s + blocked_s);
      (freeAt(mid) ? free_s : blocked_s) = mid;
    }
    if (blocking_object) clearance(x_ + blocked_s * dx, y_ + blocked_s * dy, scene, blocking_object, horizon);
    return free_s;
  }
  return 1.0;
}

StepOutcome RobotPlatform::step(double dt, const camera::SceneGeometry& scene) {
  StepOutcome outcome;
  const scenario::RobotLimits& limits = robot_.limits;
  double vx = 0, vy = 0, yaw_rate = 0;
  switch (command_.mode) {
    case MotionCommand::Mode::Stop:
    case MotionCommand::Mode::HeadOnly:
      break;
    case MotionCommand::Mode::Velocity:
      vx = command_.vx;
      vy = command_.vy;
      yaw_rate = command_.yaw_rate;
      break;
    case MotionCommand::Mode::Goto: {
      const double ex = command_.goal_x - x_, ey = command_.goal_y - y_;
      const double distance = std::hypot(ex, ey);
      if (distance > 0) {
        const double speed = std::min(limits.max_speed, distance / dt);
        vx = speed * ex / distance;
        vy = speed * ey / distance;
      }
      const double heading_error = wrapDegrees(command_.goal_yaw - yaw_);
      yaw_rate = std::clamp(heading_error / dt, -limits.max_turn_rate, limits.max_turn_rate);
      break;
    }
  }
  if (command_.set_head) {
    head_yaw_target_ = command_.head_yaw;
    head_pitch_target_ = command_.head_pitch;
  }

  // Translation, stopped at contact.
  int blocking_object = -1;
  const double dx = vx * dt, dy = vy * dt;
  const double fraction = clearFraction(dx, dy, scene, &blocking_object);
  outcome.collided = fraction < 1.0;
  outcome.blocking_object = outcome.collided ? blocking_object : -1;
  x_ += fraction * dx;
  y_ += fraction * dy;
  outcome.distance = fraction * std::hypot(dx, dy);

  // Rotation of the platform and the head, within their rate limits.
  const double turn = yaw_rate * dt;
  yaw_ = wrapDegrees(yaw_ + turn);
  const double head_step = limits.head_turn_rate * dt;
  head_yaw_ = approach(head_yaw_, head_yaw_target_, head_step);
  head_pitch_ = approach(head_pitch_, head_pitch_target_, head_step);

  vx_ = fraction * dx / dt;
  vy_ = fraction * dy / dt;
  yaw_rate_ = turn / dt;
  path_length_ += outcome.distance;
  collided_ = outcome.collided;
  if (outcome.collided) {
    const double step = std::hypot(dx, dy);
    contact_x_ = x_ + robot_.radius * dx / step;
    contact_y_ = y_ + robot_.radius * dy / step;
    contact_heading_ = std::atan2(dy, dx) * 180.0 / M_PI;
  }
  if (outcome.collided) ++collisions_;
  return outcome;
}

}  // namespace beft::world

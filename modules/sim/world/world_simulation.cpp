#include "sim/world/world_simulation.hpp"

#include <cmath>
#include <cstdio>

namespace beft::world {

namespace {

std::string formatPosition(double x, double y) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "(%.3f, %.3f)", x, y);
  return buffer;
}

beft::scene_object_t objectMessage(const scenario::Object& object, int64_t utime) {
  beft::scene_object_t message;
  message.utime = utime;
  message.id = object.id;
  message.label = object.label;
  message.activity = object.activity;
  message.x = object.x;
  message.y = object.y;
  message.z = object.z;
  message.yaw = object.yaw;
  message.shape = beft::scene_object_t::SHAPE_NONE;
  message.size_x = message.size_y = message.size_z = message.radius = 0;
  message.color_rgb = 0;
  if (object.visual) {
    const scenario::Visual& visual = *object.visual;
    message.color_rgb = static_cast<int32_t>(visual.color_rgb);
    if (visual.shape == scenario::Visual::Shape::Box) {
      message.shape = beft::scene_object_t::SHAPE_BOX;
      message.size_x = visual.size_x;
      message.size_y = visual.size_y;
      message.size_z = visual.size_z;
    } else {
      message.shape = beft::scene_object_t::SHAPE_CYLINDER;
      message.size_x = message.size_y = 2 * visual.radius;
      message.size_z = visual.height;
      message.radius = visual.radius;
    }
  }
  message.has_acoustic = object.acoustic.has_value();
  message.sound_active = object.acoustic && object.acoustic->active;
  message.sound = object.acoustic ? object.acoustic->sound : "";
  message.acoustic_label = object.acousticLabel();
  message.level = object.acoustic ? object.acoustic->level : 0.0;
  return message;
}

}  // namespace

WorldSimulation::WorldSimulation(const scenario::Scenario& scenario, const WorldOptions& options)
    : scenario_(scenario),
      options_(options),
      timeline_(std::make_unique<SceneTimeline>(scenario_)),
      robot_(scenario_.robot, scenario_.world) {
  for (const scenario::Object& object : scenario_.objects) object_ids_.push_back(object.id);
  caster_.setThreads(options_.render_threads);
  geometry_ = camera::SceneGeometry::fromObjects(timeline_->objects());
  notes_ = timeline_->startupNotes();
  for (const std::string& change : timeline_->changes()) notes_.push_back(change);
  int overlapped = -1;
  if (robot_.clearance(robot_.x(), robot_.y(), geometry_, &overlapped) < 0) {
    notes_.push_back("robot starts overlapping " +
                     (overlapped >= 0 ? "object '" + object_ids_[overlapped] + "'" : std::string("the world's edge")) +
                     "; it may only move out of it");
  }
}

int64_t WorldSimulation::utime() const { return std::llround(time() * 1e6); }

CommandCheck WorldSimulation::submitCommand(const beft::robot_command_t& command) {
  CommandCheck check = checkCommand(command, scenario_.robot, scenario_.world);
  if (check.command) robot_.setCommand(*check.command);
  return check;
}

void WorldSimulation::step() {
  notes_.clear();
  // The robot moves among the obstacles as they stand at the previous tick.
  const StepOutcome outcome = robot_.step(scenario_.dt, geometry_);
  if (timeline_->advance()) geometry_ = camera::SceneGeometry::fromObjects(timeline_->objects());
  for (const std::string& change : timeline_->changes()) notes_.push_back(change);
  if (outcome.collided) {
    // One line per contact, not per tick pushing against it.
    if (contact_object_ != outcome.blocking_object) {
      const std::string what = outcome.blocking_object >= 0 ? "object '" + object_ids_[outcome.blocking_object] + "'"
                                                             : std::string("the world's edge");
      notes_.push_back("collision at tick " + std::to_string(tick()) + ": stopped at contact with " + what +
                       " at " + formatPosition(robot_.x(), robot_.y()) + " while executing " +
                       robot_.command().description + " (stopped motions so far: " +
                       std::to_string(robot_.collisions()) + ")");
    }
    contact_object_ = outcome.blocking_object;
  } else {
    contact_object_ = -2;
  }
}

beft::scene_objects_t WorldSimulation::groundTruth() const {
  beft::scene_objects_t message{};
  message.utime = utime();
  message.tick = tick();
  message.world_width = scenario_.world.width;
  message.world_height = scenario_.world.height;
  message.scenario = scenario_.name;
  message.dt = scenario_.dt;
  message.duration = scenario_.duration;
  message.categories = scenario_.categories;
  message.num_categories = static_cast<int32_t>(message.categories.size());
  for (const auto& [key, value] : scenario_.congruency) {
    beft::congruency_entry_t entry;
    entry.label = key.first;
    entry.activity = key.second;
    entry.value = value;
    message.congruency.push_back(entry);
  }
  message.num_congruency = static_cast<int32_t>(message.congruency.size());
  for (const scenario::Object& object : objects()) message.objects.push_back(objectMessage(object, message.utime));
  message.num_objects = static_cast<int32_t>(message.objects.size());
  return message;
}

int64_t WorldSimulation::sceneTick() const {
  const int64_t now = tick();
  const int64_t keyframe = now - now % std::max(1, options_.scene_keyframe_ticks);
  return std::max(timeline_->lastChangeTick(), keyframe);
}

beft::scene_version_t WorldSimulation::sceneVersion() const {
  beft::scene_version_t version{};
  version.utime = utime();
  version.tick = tick();
  version.scene_tick = sceneTick();
  return version;
}

beft::robot_state_t WorldSimulation::robotState() const {
  beft::robot_state_t state{};
  state.utime = utime();
  state.tick = tick();
  state.x = robot_.x();
  state.y = robot_.y();
  state.yaw = robot_.yaw();
  state.head_yaw = robot_.headYaw();
  state.head_pitch = robot_.headPitch();
  state.vx = robot_.vx();
  state.vy = robot_.vy();
  state.yaw_rate = robot_.yawRate();
  state.radius = scenario_.robot.radius;
  state.camera_height = scenario_.robot.camera.height_above_ground;
  state.path_length = robot_.pathLength();
  state.collisions = robot_.collisions();
  state.collided = robot_.collided();
  state.last_command = robot_.command().description;
  return state;
}

beft::contact_t WorldSimulation::contact() const {
  beft::contact_t contact{};
  contact.utime = utime();
  contact.tick = tick();
  contact.touching = robot_.collided();
  contact.x = robot_.collided() ? robot_.contactX() : 0.0;
  contact.y = robot_.collided() ? robot_.contactY() : 0.0;
  contact.heading = robot_.collided() ? robot_.contactHeading() : 0.0;
  return contact;
}

camera::Camera WorldSimulation::camera() const {
  const scenario::Camera& c = scenario_.robot.camera;
  return camera::cameraOnRobot(robot_.x(), robot_.y(), robot_.yaw(), robot_.headYaw(), robot_.headPitch(),
                               c.height_above_ground, {c.fov, c.width, c.height, c.range});
}

void WorldSimulation::renderCamera(camera::RenderedFrame& frame) {
  caster_.render(geometry_, camera(), frame);
  if (options_.depth_noise > 0) {
    // Seeded by (seed, tick): the same frame whatever happened before.
    std::mt19937_64 random(options_.seed * 0x9E3779B97F4A7C15ULL + static_cast<uint64_t>(tick()));
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    const float k = static_cast<float>(options_.depth_noise);
    for (float& depth : frame.depth) {
      if (depth > 0) depth = std::max(static_cast<float>(camera::kMinDepth), depth + k * depth * depth * gauss(random));
    }
  }
}

void WorldSimulation::cameraMessages(camera::CameraMessages& messages) {
  if (options_.depth_noise > 0) {  // the noise goes on the rendered depths, before encoding
    renderCamera(frame_);
    camera::encodeCameraMessages(frame_, utime(), tick(), object_ids_, messages);
    return;
  }
  camera::renderCameraMessages(caster_, geometry_, camera(), utime(), tick(), object_ids_, messages);
}

}  // namespace beft::world

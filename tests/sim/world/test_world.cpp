// The world's logic without messaging: robot motion and its limits,
// collisions, commands refused, paths, events at their ticks, determinism
// and the ground-truth message.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/world/robot_platform.hpp"
#include "sim/world/scene_timeline.hpp"
#include "sim/world/world_simulation.hpp"
#include "tests/sim/world/world_test_scenarios.hpp"

using namespace beft::world;
using namespace beft::world::testing;
using beft::scenario::Scenario;

namespace {

beft::robot_command_t velocityCommand(double vx, double vy, double yaw_rate) {
  beft::robot_command_t command{};
  command.mode = beft::robot_command_t::MODE_VELOCITY;
  command.vx = vx;
  command.vy = vy;
  command.yaw_rate = yaw_rate;
  command.source = "test";
  return command;
}

beft::robot_command_t gotoCommand(double x, double y, double yaw) {
  beft::robot_command_t command{};
  command.mode = beft::robot_command_t::MODE_GOTO;
  command.goal_x = x;
  command.goal_y = y;
  command.goal_yaw = yaw;
  return command;
}

bool notesMention(const WorldSimulation& world, const std::string& text) {
  for (const std::string& note : world.notes())
    if (note.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(RobotMotion, VelocityIsLimitedToMaxSpeedAndTurnRate) {
  Scenario scenario = emptyYard();
  scenario.robot.limits.max_speed = 0.5;
  scenario.robot.limits.max_turn_rate = 45;
  WorldSimulation world(scenario, {});
  const CommandCheck check = world.submitCommand(velocityCommand(3.0, 4.0, -200));  // 5 m/s requested
  ASSERT_TRUE(check.command.has_value());
  EXPECT_NE(check.adjustments.find("max_speed"), std::string::npos);
  EXPECT_NE(check.adjustments.find("max_turn_rate"), std::string::npos);
  for (int i = 0; i < 10; ++i) world.step();
  // One second at 0.5 m/s along (0.6, 0.8), turning at -45 deg/s.
  EXPECT_NEAR(world.robot().x(), 2.0 + 0.3, 1e-9);
  EXPECT_NEAR(world.robot().y(), 2.0 + 0.4, 1e-9);
  EXPECT_NEAR(world.robot().yaw(), -45.0, 1e-9);
  EXPECT_NEAR(std::hypot(world.robot().vx(), world.robot().vy()), 0.5, 1e-9);
  EXPECT_NEAR(world.robot().pathLength(), 0.5, 1e-9);
  const beft::robot_state_t state = world.robotState();
  EXPECT_EQ(state.tick, 10);
  EXPECT_EQ(state.utime, 1000000);
  EXPECT_NE(state.last_command.find("velocity"), std::string::npos);
  EXPECT_FALSE(state.collided);
}

TEST(RobotMotion, GotoDrivesAtMaxSpeedAndStopsExactlyAtTheGoal) {
  Scenario scenario = emptyYard();
  WorldSimulation world(scenario, {});
  ASSERT_TRUE(world.submitCommand(gotoCommand(8.0, 10.0, 120.0)).command);
  // 10 m away at 1 m/s: 100 ticks; the turn of 120 deg at 90 deg/s takes 14.
  double previous_x = world.robot().x(), previous_y = world.robot().y();
  for (int i = 0; i < 99; ++i) {
    world.step();
    const double moved = std::hypot(world.robot().x() - previous_x, world.robot().y() - previous_y);
    EXPECT_LE(moved, 0.1 + 1e-12);
    previous_x = world.robot().x();
    previous_y = world.robot().y();
  }
  EXPECT_GT(std::hypot(world.robot().x() - 8, world.robot().y() - 10), 0.05);
  world.step();
  EXPECT_NEAR(world.robot().x(), 8.0, 1e-9);
  EXPECT_NEAR(world.robot().y(), 10.0, 1e-9);
  EXPECT_NEAR(world.robot().yaw(), 120.0, 1e-9);
  world.step();  // and stays there
  EXPECT_NEAR(world.robot().x(), 8.0, 1e-9);
  EXPECT_EQ(world.robot().vx(), 0.0);
  EXPECT_EQ(world.robot().collisions(), 0);
}

TEST(RobotMotion, RefusesToDriveThroughAWallAndReportsTheCollision) {
  Scenario scenario = emptyYard();
  // A wall across the robot's way: its face at x = 5.
  scenario.objects.push_back(boxObject("wall1", "wall", 5.1, 2.0, 90.0, 6.0, 0.2, 2.5));
  WorldSimulation world(scenario, {});
  world.submitCommand(gotoCommand(8.0, 2.0, 0.0));
  bool logged = false;
  for (int i = 0; i < 80; ++i) {
    world.step();
    logged = logged || notesMention(world, "wall1");
  }
  // Stopped at contact: the disc (radius 0.35) touches the face at x = 5.
  EXPECT_NEAR(world.robot().x(), 5.0 - 0.35, 1e-6);
  EXPECT_LE(world.robot().x(), 5.0 - 0.35 + 1e-9);
  EXPECT_TRUE(world.robot().collided());
  EXPECT_GT(world.robot().collisions(), 0);
  EXPECT_TRUE(logged);
  const beft::robot_state_t state = world.robotState();
  EXPECT_TRUE(state.collided);
  EXPECT_EQ(state.collisions, world.robot().collisions());
  EXPECT_NEAR(state.path_length, 5.0 - 0.35 - 2.0, 1e-6);
  // Backing off is allowed and clears the flag.
  world.submitCommand(velocityCommand(-1.0, 0.0, 0.0));
  world.step();
  EXPECT_NEAR(world.robot().x(), 5.0 - 0.35 - 0.1, 1e-6);
  EXPECT_FALSE(world.robot().collided());
}

TEST(RobotMotion, PersonsAndTheWorldEdgeBlockToo) {
  Scenario scenario = emptyYard();
  scenario.objects.push_back(personObject("victim", 2.0, 6.0));
  WorldSimulation world(scenario, {});
  world.submitCommand(velocityCommand(0.0, 1.0, 0.0));
  for (int i = 0; i < 50; ++i) world.step();
  EXPECT_NEAR(world.robot().y(), 6.0 - 0.3 - 0.35, 1e-6);
  EXPECT_TRUE(world.robot().collided());

  WorldSimulation edge(scenario, {});
  edge.submitCommand(velocityCommand(-1.0, 0.0, 0.0));
  for (int i = 0; i < 30; ++i) edge.step();
  EXPECT_NEAR(edge.robot().x(), 0.35, 1e-6);
  EXPECT_TRUE(edge.robot().collided());
}

TEST(RobotMotion, FastMotionCannotTunnelThroughAThinWall) {
  Scenario scenario = emptyYard();
  scenario.robot.limits.max_speed = 20;  // 2 m per tick, wall 5 cm thick
  scenario.objects.push_back(boxObject("thin", "wall", 5.0, 2.0, 0.0, 0.05, 4.0, 2.0));
  WorldSimulation world(scenario, {});
  world.submitCommand(velocityCommand(20.0, 0.0, 0.0));
  for (int i = 0; i < 5; ++i) world.step();
  EXPECT_NEAR(world.robot().x(), 5.0 - 0.025 - 0.35, 1e-6);
}

TEST(RobotMotion, InvalidCommandsAreRefusedAndTheCommandInForceStays) {
  Scenario scenario = emptyYard();
  WorldSimulation world(scenario, {});
  ASSERT_TRUE(world.submitCommand(velocityCommand(0.5, 0.0, 0.0)).command);

  beft::robot_command_t unknown = velocityCommand(0, 0, 0);
  unknown.mode = 42;
  CommandCheck check = world.submitCommand(unknown);
  EXPECT_FALSE(check.command);
  EXPECT_NE(check.refusal.find("unknown mode 42"), std::string::npos);

  check = world.submitCommand(velocityCommand(NAN, 0.0, 0.0));
  EXPECT_FALSE(check.command);
  EXPECT_NE(check.refusal.find("non-finite"), std::string::npos);

  check = world.submitCommand(gotoCommand(45.0, 2.0, 0.0));
  EXPECT_FALSE(check.command);
  EXPECT_NE(check.refusal.find("outside the world"), std::string::npos);

  beft::robot_command_t bad_head = velocityCommand(0, 0, 0);
  bad_head.set_head = true;
  bad_head.head_yaw = INFINITY;
  EXPECT_FALSE(world.submitCommand(bad_head).command);

  world.step();
  EXPECT_NEAR(world.robot().x(), 2.05, 1e-9);  // still the first command
}

TEST(RobotMotion, HeadTurnsAtItsRateWithinItsRange) {
  Scenario scenario = emptyYard();
  scenario.robot.limits.head_turn_rate = 100;  // 10 deg per tick
  WorldSimulation world(scenario, {});
  beft::robot_command_t command{};
  command.mode = beft::robot_command_t::MODE_HEAD_ONLY;
  command.head_yaw = 120;   // beyond +/-85: clamped
  command.head_pitch = -8;
  const CommandCheck check = world.submitCommand(command);
  ASSERT_TRUE(check.command);
  EXPECT_NE(check.adjustments.find("head_yaw"), std::string::npos);
  world.step();
  EXPECT_NEAR(world.robot().headYaw(), 10.0, 1e-9);
  EXPECT_NEAR(world.robot().headPitch(), -8.0, 1e-9);
  for (int i = 0; i < 20; ++i) world.step();
  EXPECT_NEAR(world.robot().headYaw(), 85.0, 1e-9);
  EXPECT_EQ(world.robot().x(), 2.0);  // the platform stood still
  // The camera looks where the head points.
  EXPECT_NEAR(world.camera().pose.yaw_deg, 85.0, 1e-9);
  EXPECT_NEAR(world.camera().pose.pitch_deg, -8.0, 1e-9);
}

TEST(SceneTimeline, PathsMoveObjectsAtTheirSpeedAndFaceTheirWay) {
  beft::scenario::Path path;
  path.object = "walker";
  path.speed = 1.0;
  path.waypoints = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}};
  PathPoint point = pathPointAt(path, 2.5);
  EXPECT_NEAR(point.x, 2.5, 1e-12);
  EXPECT_NEAR(point.y, 0.0, 1e-12);
  EXPECT_NEAR(point.yaw, 0.0, 1e-12);
  point = pathPointAt(path, 5.0);
  EXPECT_NEAR(point.x, 4.0, 1e-12);
  EXPECT_NEAR(point.y, 1.0, 1e-12);
  EXPECT_NEAR(point.yaw, 90.0, 1e-12);
  point = pathPointAt(path, 100.0);  // stops at the end
  EXPECT_NEAR(point.x, 4.0, 1e-12);
  EXPECT_NEAR(point.y, 4.0, 1e-12);
  path.loop = true;                  // 4 + 4 + sqrt(32) around
  point = pathPointAt(path, 8.0 + std::sqrt(32.0) / 2);
  EXPECT_NEAR(point.x, 2.0, 1e-9);
  EXPECT_NEAR(point.y, 2.0, 1e-9);
  EXPECT_NEAR(point.yaw, -135.0, 1e-9);
  point = pathPointAt(path, 8.0 + std::sqrt(32.0) + 1.0);  // second lap
  EXPECT_NEAR(point.x, 1.0, 1e-9);
}

TEST(SceneTimeline, WorldMovesPathObjectsAndTheCameraSeesThem) {
  Scenario scenario = emptyYard();
  scenario.objects.push_back(personObject("walker", 10.0, 2.0));
  beft::scenario::Path path;
  path.object = "walker";
  path.speed = 0.5;
  path.waypoints = {{10, 2, 0}, {10, 12, 0}};
  scenario.paths.push_back(path);
  WorldSimulation world(scenario, {});
  for (int i = 0; i < 40; ++i) world.step();  // 4 s at 0.5 m/s
  const beft::scene_objects_t truth = world.groundTruth();
  EXPECT_NEAR(truth.objects[0].x, 10.0, 1e-12);
  EXPECT_NEAR(truth.objects[0].y, 4.0, 1e-9);
  // The geometry follows: a segment through the walker's new place is blocked.
  EXPECT_TRUE(beft::camera::segmentBlocked(world.geometry(), {9, 4, 1}, {11, 4, 1}));
  EXPECT_FALSE(beft::camera::segmentBlocked(world.geometry(), {9, 2, 1}, {11, 2, 1}));
}

TEST(SceneTimeline, EventsApplyAtTheirTicksInTimeOrder) {
  Scenario scenario = emptyYard();
  scenario.objects.push_back(personObject("walker", 10.0, 5.0));
  scenario.objects.back().activity = "walking";
  scenario.objects.back().acoustic = beft::scenario::Acoustic{};
  scenario.objects.back().acoustic->sound = "sounds/talk.wav";
  scenario.objects.back().acoustic->active = false;
  scenario.objects.push_back(boxObject("fire1", "fire", 20.0, 10.0, 0.0, 1, 1, 1));
  const auto event = [](double t, const std::string& object) {
    beft::scenario::Event e;
    e.t = t;
    e.object = object;
    return e;
  };
  auto at0 = event(0.0, "fire1");
  at0.activity = "burning";
  auto yelling = event(1.2, "walker");
  yelling.activity = "yelling";
  yelling.active = true;
  yelling.sound = "sounds/help.wav";
  auto between = event(1.25, "fire1");  // between ticks 12 and 13: applies at 13
  between.activity = "spreading";
  auto moved = event(1.25, "fire1");    // same time, later in the file: after it
  moved.x = 21.0;
  moved.activity = "burning";
  auto quiet = event(3.0, "walker");
  quiet.active = false;
  scenario.events = {at0, yelling, between, moved, quiet};

  EXPECT_EQ(eventTick(1.2, 0.1), 12);
  EXPECT_EQ(eventTick(1.25, 0.1), 13);
  EXPECT_EQ(eventTick(0.3, 0.1), 3);  // 0.3 / 0.1 is 2.9999999999999996

  WorldSimulation world(scenario, {});
  EXPECT_EQ(world.objects()[1].activity, "burning");  // t = 0 applies at tick 0
  while (world.tick() < 11) world.step();
  EXPECT_EQ(world.objects()[0].activity, "walking");
  EXPECT_FALSE(world.groundTruth().objects[0].sound_active);
  world.step();  // tick 12
  EXPECT_EQ(world.objects()[0].activity, "yelling");
  const beft::scene_objects_t at12 = world.groundTruth();
  EXPECT_TRUE(at12.objects[0].sound_active);
  EXPECT_EQ(at12.objects[0].sound, "sounds/help.wav");
  EXPECT_TRUE(notesMention(world, "walker activity yelling"));
  EXPECT_EQ(world.objects()[1].activity, "burning");
  world.step();  // tick 13: both fire1 events, in file order
  EXPECT_EQ(world.objects()[1].activity, "burning");
  EXPECT_EQ(world.objects()[1].x, 21.0);
  EXPECT_EQ(world.notes().size(), 2u);
  while (world.tick() < 29) world.step();
  EXPECT_TRUE(world.groundTruth().objects[0].sound_active);
  world.step();  // tick 30
  EXPECT_FALSE(world.groundTruth().objects[0].sound_active);
}

TEST(WorldSimulation, TheGroundTruthInForceIsTheLastChangeOrKeyframe) {
  // Events at ticks 12 and 30, keyframes every 25 ticks: GT_OBJECTS goes out
  // at 0, 12, 25, 30 and 50, and GT_VERSION names the one in force.
  Scenario scenario = emptyYard();
  scenario.objects.push_back(personObject("caller", 10.0, 5.0));
  scenario.objects.back().acoustic = beft::scenario::Acoustic{};
  scenario.objects.back().acoustic->sound = "sounds/help.wav";
  scenario.objects.back().acoustic->active = false;
  beft::scenario::Event calls, quiet;
  calls.t = 1.2, calls.object = "caller", calls.active = true;
  quiet.t = 3.0, quiet.object = "caller", quiet.active = false;
  scenario.events = {calls, quiet};
  WorldOptions options;
  options.scene_keyframe_ticks = 25;
  WorldSimulation world(scenario, options);
  std::vector<int64_t> published;
  bool sounding_before = false;
  for (int64_t k = 0; k <= 55; ++k) {
    if (k > 0) world.step();
    const beft::scene_version_t version = world.sceneVersion();
    EXPECT_EQ(version.tick, k);
    EXPECT_EQ(version.utime, k * 100000);
    EXPECT_LE(version.scene_tick, k);
    if (version.scene_tick == k) published.push_back(k);
    // Whatever tick it is, the ground truth in force says what the world does now.
    const bool sounding = world.groundTruth().objects[0].sound_active;
    if (version.scene_tick != k) {
      EXPECT_EQ(sounding, sounding_before) << "tick " << k;
    }
    sounding_before = sounding;
  }
  EXPECT_EQ(published, (std::vector<int64_t>{0, 12, 25, 30, 50}));

  // An object on its path changes the scene at every tick it moves.
  Scenario walking = emptyYard();
  walking.objects.push_back(personObject("walker", 10.0, 2.0));
  beft::scenario::Path path;
  path.object = "walker";
  path.speed = 1.0;
  path.waypoints = {{10, 2, 0}, {10, 3, 0}};  // 1 m: moves during ticks 1..10
  walking.paths.push_back(path);
  WorldSimulation walker(walking, options);
  for (int k = 1; k <= 14; ++k) {
    walker.step();
    EXPECT_EQ(walker.sceneTick(), std::min(k, 10)) << "tick " << k;
  }
}

TEST(WorldSimulation, GroundTruthDescribesTheScenario) {
  Scenario scenario = emptyYard();
  scenario.objects.push_back(boxObject("wall1", "wall", 10, 8, 90, 4, 0.2, 2.5));
  scenario.objects.push_back(personObject("victim1", 12, 8));
  beft::scenario::Object radio;
  radio.id = "radio";
  radio.label = "siren";
  radio.x = 20;
  radio.y = 15;
  radio.acoustic = beft::scenario::Acoustic{};
  radio.acoustic->sound = "sounds/siren.wav";
  radio.acoustic->label = "person";
  scenario.objects.push_back(radio);
  scenario.congruency[{"person", "yelling"}] = 0.75;
  WorldSimulation world(scenario, {});
  const beft::scene_objects_t truth = world.groundTruth();
  EXPECT_EQ(truth.tick, 0);
  EXPECT_EQ(truth.scenario, "test_yard");
  EXPECT_EQ(truth.world_width, 30);
  ASSERT_EQ(truth.num_objects, 3);
  EXPECT_EQ(truth.objects[0].id, "wall1");
  EXPECT_EQ(truth.objects[0].shape, beft::scene_object_t::SHAPE_BOX);
  EXPECT_EQ(truth.objects[0].size_x, 4);
  EXPECT_EQ(truth.objects[0].yaw, 90);
  EXPECT_EQ(truth.objects[1].shape, beft::scene_object_t::SHAPE_CYLINDER);
  EXPECT_EQ(truth.objects[1].radius, 0.3);
  EXPECT_EQ(truth.objects[1].color_rgb, 0xd04040);
  EXPECT_EQ(truth.objects[2].shape, beft::scene_object_t::SHAPE_NONE);
  EXPECT_EQ(truth.objects[2].acoustic_label, "person");
  EXPECT_TRUE(truth.objects[2].sound_active);
  ASSERT_EQ(truth.num_congruency, 1);
  EXPECT_EQ(truth.congruency[0].value, 0.75);
  EXPECT_EQ(truth.num_categories, 5);
  // An expert's geometry from the message matches the world's own.
  const auto from_message = beft::camera::SceneGeometry::fromMessage(truth);
  ASSERT_EQ(from_message.solids().size(), world.geometry().solids().size());
  EXPECT_EQ(from_message.solidOfObject(2), -1);
  EXPECT_EQ(from_message.solids()[1].radius, 0.3);
}

TEST(WorldSimulation, SameScenarioSeedAndCommandsGiveTheSameOutputs) {
  Scenario scenario = emptyYard();
  scenario.objects.push_back(boxObject("wall1", "wall", 6, 4, 30, 4, 0.2, 2.5));
  scenario.objects.push_back(personObject("walker", 12, 3));
  beft::scenario::Path path;
  path.object = "walker";
  path.speed = 0.8;
  path.loop = true;
  path.waypoints = {{12, 3, 0}, {12, 9, 0}, {16, 9, 0}};
  scenario.paths.push_back(path);
  WorldOptions options;
  options.seed = 99;
  options.depth_noise = 0.01;
  const auto run = [&](std::vector<std::vector<uint8_t>>& outputs) {
    WorldSimulation world(scenario, options);
    beft::camera::CameraMessages messages;
    for (int k = 0; k <= 60; ++k) {
      if (k == 5) world.submitCommand(velocityCommand(0.6, 0.4, 20));
      if (k == 30) world.submitCommand(gotoCommand(20, 15, -90));
      if (k > 0) world.step();
      const auto encode = [&outputs](const auto& message) {
        std::vector<uint8_t> bytes(message.getEncodedSize());
        message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
        outputs.push_back(std::move(bytes));
      };
      encode(world.groundTruth());
      encode(world.robotState());
      world.cameraMessages(messages);
      encode(messages.color);
      encode(messages.depth);
      encode(messages.instance);
    }
  };
  std::vector<std::vector<uint8_t>> first, second;
  run(first);
  run(second);
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) EXPECT_EQ(first[i], second[i]) << "message " << i;
  // A different seed changes the depth noise, hence the depth images.
  options.seed = 100;
  std::vector<std::vector<uint8_t>> third;
  run(third);
  EXPECT_NE(first[3], third[3]);  // tick 0 depth
  EXPECT_EQ(first[2], third[2]);  // colour is not noisy
}

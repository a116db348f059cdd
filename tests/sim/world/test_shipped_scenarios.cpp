// The world on the shipped scenarios: fig4_dw's events at their ticks, and
// the yard's walls stopping the robot.
#include <gtest/gtest.h>

#include <string>

#include "lib/scenario/load_scenario.hpp"
#include "lib/scene/ray_caster.hpp"
#include "sim/world/world_simulation.hpp"

using beft::world::WorldSimulation;

namespace {

const std::string kScenarioDir = BEFT_SCENARIO_DIR;

int indexOf(const WorldSimulation& world, const std::string& id) {
  for (size_t i = 0; i < world.objectIds().size(); ++i)
    if (world.objectIds()[i] == id) return static_cast<int>(i);
  return -1;
}

void stepTo(WorldSimulation& world, int64_t tick) {
  while (world.tick() < tick) world.step();
}

}  // namespace

TEST(ShippedScenarios, Fig4EventsApplyAtTheirTicks) {
  const auto scenario = beft::scenario::loadScenario(kScenarioDir + "/fig4_dw.xml", nullptr);
  WorldSimulation world(scenario, {});
  const int walker = indexOf(world, "walker"), fire = indexOf(world, "fire1");
  ASSERT_GE(walker, 0);
  ASSERT_GE(fire, 0);
  const auto walkerState = [&] { return world.groundTruth().objects[walker]; };

  // t = 10 s: yelling with help.wav, from tick 100 on.
  stepTo(world, 99);
  EXPECT_EQ(walkerState().activity, "walking");
  EXPECT_EQ(walkerState().sound, "sounds/talk.wav");
  world.step();
  EXPECT_EQ(walkerState().activity, "yelling");
  EXPECT_EQ(walkerState().sound, "sounds/help.wav");
  EXPECT_TRUE(walkerState().sound_active);
  // t = 25 s: walking and talking again at tick 250.
  stepTo(world, 249);
  EXPECT_EQ(walkerState().activity, "yelling");
  world.step();
  EXPECT_EQ(walkerState().activity, "walking");
  EXPECT_EQ(walkerState().sound, "sounds/talk.wav");
  // t = 30 s: the fire spreads at tick 300.
  stepTo(world, 299);
  EXPECT_EQ(world.groundTruth().objects[fire].activity, "burning");
  world.step();
  EXPECT_EQ(world.groundTruth().objects[fire].activity, "spreading");
  EXPECT_EQ(world.groundTruth().objects[walker].activity, "walking");

  // Meanwhile the walker paces its path at 0.6 m/s: (8, 3.5) <-> (8, 9),
  // 11 m per lap; at t = 30 s it has walked 18 m: 1 lap + 7 m, i.e. 1.5 m
  // down from (8, 9).
  EXPECT_NEAR(walkerState().x, 8.0, 1e-9);
  EXPECT_NEAR(walkerState().y, 7.5, 1e-9);
  EXPECT_NEAR(walkerState().yaw, -90.0, 1e-9);
}

TEST(ShippedScenarios, YardWallStopsTheRobot) {
  const auto scenario = beft::scenario::loadScenario(kScenarioDir + "/yard.xml", nullptr);
  WorldSimulation world(scenario, {});
  // North along the west edge, then east at y = 9.3: clear of building_wall
  // (y 9.9 .. 10.1) and debris3, straight into nook_west (x 16.9 .. 17.1).
  beft::robot_command_t command{};
  command.mode = beft::robot_command_t::MODE_GOTO;
  command.goal_x = 3.0;
  command.goal_y = 9.3;
  ASSERT_TRUE(world.submitCommand(command).command);
  stepTo(world, 90);
  EXPECT_NEAR(world.robot().x(), 3.0, 1e-9);
  EXPECT_NEAR(world.robot().y(), 9.3, 1e-9);
  EXPECT_EQ(world.robot().collisions(), 0);

  command.goal_x = 20.0;
  ASSERT_TRUE(world.submitCommand(command).command);
  bool reported = false;
  while (world.tick() < 260) {
    world.step();
    for (const std::string& note : world.notes()) reported = reported || note.find("nook_west") != std::string::npos;
  }
  EXPECT_NEAR(world.robot().x(), 16.9 - scenario.robot.radius, 1e-6);
  EXPECT_NEAR(world.robot().y(), 9.3, 1e-9);
  EXPECT_TRUE(world.robot().collided());
  EXPECT_GT(world.robotState().collisions, 0);
  EXPECT_TRUE(reported);

  // Facing east at the wall: it fills the centre of the camera image.
  beft::camera::RenderedFrame frame;
  world.renderCamera(frame);
  const int nook_west = indexOf(world, "nook_west");
  EXPECT_EQ(frame.object[60 * 160 + 80], nook_west);
  EXPECT_NEAR(frame.depth[60 * 160 + 80], 16.9 - world.robot().x(), 1e-5);
}

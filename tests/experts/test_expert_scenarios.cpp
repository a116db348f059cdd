// The expert hierarchy on the shipped scenarios: the world and the six
// experts in one process (the same Expert classes as the live processes),
// the robot driven along a fixed route, checking what fusion concludes.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include <beft/hypotheses_t.hpp>
#include <beft/obstacle_map_t.hpp>

#include "lib/common/channels.hpp"
#include "tools/bench_experts/expert_chain.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/wire/obstacle_map_codec.hpp"
#include "sim/world/world_simulation.hpp"

using namespace beft;

namespace {

class ScenarioRun {
 public:
  explicit ScenarioRun(const std::string& name)
      : scenario_(scenario::loadScenario(std::string(BEFT_SCENARIO_DIR) + "/" + name + ".xml")),
        world_(scenario_, world::WorldOptions{scenario_.seed, 0}) {
    runTick();
  }

  // Drives to a pose with MODE_GOTO, running the experts every tick; false if
  // the robot did not get there within max_ticks.
  bool driveTo(double x, double y, double yaw_deg, int max_ticks = 400) {
    robot_command_t command{};
    command.mode = robot_command_t::MODE_GOTO;
    command.goal_x = x;
    command.goal_y = y;
    command.goal_yaw = yaw_deg;
    command.source = "test";
    if (!world_.submitCommand(command).command) return false;
    for (int i = 0; i < max_ticks; ++i) {
      world_.step();
      runTick();
      const auto robot = world_.robotState();
      const double yaw_error = std::remainder(robot.yaw - yaw_deg, 360.0);
      if (std::hypot(robot.x - x, robot.y - y) < 1e-6 && std::abs(yaw_error) < 1e-6) return true;
    }
    return false;
  }

  hypothesis_t hypothesis(const std::string& id) const {
    hypotheses_t all{};
    if (!chain_.latestHypotheses(all)) throw std::runtime_error("no HYPOTHESES yet");
    for (const auto& h : all.hypotheses)
      if (h.object_id == id) return h;
    throw std::runtime_error("no hypothesis for " + id);
  }
  bool hasHypothesis(const std::string& id) const {
    try {
      hypothesis(id);
      return true;
    } catch (const std::runtime_error&) {
      return false;
    }
  }
  planners::ObstacleCells obstacleMap() const {
    const auto map = chain_.latestObstacleMap();
    if (map == nullptr) throw std::runtime_error("no OBSTACLE_MAP yet");
    return *map;
  }
  int64_t utime() const { return world_.utime(); }
  const std::vector<std::string>& failures() const { return failures_; }
  const world::WorldSimulation& world() const { return world_; }

 private:
  void runTick() {
    world_.cameraMessages(frames_);
    const auto problems = chain_.runTick(world_.groundTruth(), world_.robotState(), frames_.depth, frames_.instance);
    failures_.insert(failures_.end(), problems.begin(), problems.end());
  }

  scenario::Scenario scenario_;
  world::WorldSimulation world_;
  bench::ExpertChain chain_;
  camera::CameraMessages frames_;
  std::vector<std::string> failures_;
};

int occupiedCellsIn(const planners::ObstacleCells& map, double x0, double x1, double y0, double y1) {
  int count = 0;
  for (int row = static_cast<int>(y0 / map.resolution); row < static_cast<int>(y1 / map.resolution); ++row)
    for (int column = static_cast<int>(x0 / map.resolution); column < static_cast<int>(x1 / map.resolution); ++column)
      count += map.at(column, row) == obstacle_map_t::CELL_OCCUPIED;
  return count;
}

}  // namespace

TEST(ExpertScenarios, PeekHearsTheHiddenVictimFirstAndVerifiesItAroundTheWall) {
  ScenarioRun run("peek");
  hypothesis_t victim = run.hypothesis("victim");
  EXPECT_TRUE(victim.heard);
  EXPECT_FALSE(victim.seen);  // behind long_wall
  EXPECT_EQ(victim.heard_as, "person");
  EXPECT_EQ(victim.first_heard_utime, 0);
  EXPECT_FALSE(victim.verified);

  // Round the south end of long_wall (x = 10, y 3..12), then look at the victim.
  ASSERT_TRUE(run.driveTo(8, 1.5, 0));
  EXPECT_FALSE(run.hypothesis("victim").seen);
  ASSERT_TRUE(run.driveTo(13, 1.5, 72));
  victim = run.hypothesis("victim");
  EXPECT_TRUE(victim.seen);
  EXPECT_EQ(victim.seen_as, "person");
  EXPECT_TRUE(victim.verified);
  EXPECT_FALSE(victim.falsified);
  EXPECT_GT(victim.first_seen_utime, victim.first_heard_utime);
  EXPECT_EQ(victim.settled_utime, victim.first_seen_utime);
  EXPECT_NEAR(victim.x, 15.0, 1e-9);  // placed by vision now
  EXPECT_NEAR(victim.y, 7.5, 1e-9);
  EXPECT_EQ(victim.best_category, "person");
  EXPECT_GT(victim.confidence, 0.9);

  // The camera has mapped long_wall's west face on the way, and the floor in front of it.
  const auto map = run.obstacleMap();
  EXPECT_GT(occupiedCellsIn(map, 9.7, 10.0, 3.0, 12.0), 40);
  EXPECT_EQ(occupiedCellsIn(map, 3.0, 9.0, 4.0, 11.0), 0);
  EXPECT_TRUE(run.failures().empty()) << run.failures().front();
}

TEST(ExpertScenarios, DecoyRadioThatSoundsLikeAPersonIsFalsifiedOnSight) {
  ScenarioRun run("decoy");
  hypothesis_t radio = run.hypothesis("radio");
  EXPECT_TRUE(radio.heard);
  EXPECT_FALSE(radio.seen);  // behind screen_wall
  EXPECT_EQ(radio.heard_as, "person");
  EXPECT_EQ(radio.best_category, "person");
  EXPECT_FALSE(run.hasHypothesis("victim"));  // silent and out of view

  // East of screen_wall (x 6..18 along y = 12), then face the radio from 8.5 m.
  ASSERT_TRUE(run.driveTo(20.5, 9, 0));  // facing east: the lying victim comes into view
  ASSERT_TRUE(run.driveTo(20.5, 15, 180));
  radio = run.hypothesis("radio");
  EXPECT_TRUE(radio.seen);
  EXPECT_EQ(radio.seen_as, "siren");
  EXPECT_EQ(radio.heard_as, "person");
  EXPECT_TRUE(radio.falsified);
  EXPECT_FALSE(radio.verified);
  EXPECT_GT(radio.settled_utime, 0);

  // The silent victim lying at (20, 6) came into view on the way.
  ASSERT_TRUE(run.hasHypothesis("victim"));
  const hypothesis_t victim = run.hypothesis("victim");
  EXPECT_FALSE(victim.heard);
  EXPECT_EQ(victim.best_category, "person");
  EXPECT_TRUE(run.failures().empty()) << run.failures().front();
}

TEST(ExpertScenarios, YardFirstTickSeesOneVictimAndHearsTheOthers) {
  ScenarioRun run("yard");
  const hypothesis_t seen = run.hypothesis("victim_seen");
  EXPECT_TRUE(seen.seen);
  EXPECT_FALSE(seen.heard);
  EXPECT_EQ(seen.seen_as, "person");
  const hypothesis_t hidden = run.hypothesis("victim_hidden");
  EXPECT_TRUE(hidden.heard);
  EXPECT_FALSE(hidden.seen);
  EXPECT_EQ(hidden.heard_as, "person");
  EXPECT_TRUE(run.hypothesis("siren1").heard);
  EXPECT_EQ(run.hypothesis("siren1").heard_as, "siren");
  EXPECT_TRUE(run.hypothesis("car1").heard);
  EXPECT_TRUE(run.failures().empty()) << run.failures().front();
}

#include "lib/wire/obstacle_map_codec.hpp"
#include "services/planner/planner_service.hpp"
#include "tests/planners/planner_test_support.hpp"
#include "planners/planning_map.hpp"

#include <beft/plan_request_t.hpp>
#include <beft/plan_result_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <cmath>
#include <csignal>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

namespace beft::planner_service {
namespace {

namespace bp = beft::planners;

constexpr uint8_t kUnknown = beft::obstacle_map_t::CELL_UNKNOWN;
constexpr uint8_t kFree = beft::obstacle_map_t::CELL_FREE;
constexpr uint8_t kOccupied = beft::obstacle_map_t::CELL_OCCUPIED;

// A 10 x 6 m world at 0.1 m per cell, origin (-2, 1): a wall at x = 3 m from
// y = 1 m to 5.5 m (seen), the rest free or unknown.
bp::ObstacleCells wallWorld() {
  bp::ObstacleCells map;
  map.width = 100;
  map.height = 60;
  map.resolution = 0.1;
  map.origin_x = -2.0;
  map.origin_y = 1.0;
  map.cells.assign(6000, kUnknown);
  for (int y = 0; y < 60; ++y) {
    for (int x = 0; x < 50; ++x) map.cells[y * 100 + x] = kFree;
  }
  for (int y = 0; y < 45; ++y) {
    for (int x = 50; x < 52; ++x) map.cells[y * 100 + x] = kOccupied;
  }
  return map;
}

beft::plan_request_t request(int64_t id, double sx, double sy, double gx, double gy, const std::string& planner = "") {
  beft::plan_request_t r{};
  r.request_id = id;
  r.start_x = sx;
  r.start_y = sy;
  r.start_yaw = 0;
  r.goal_x = gx;
  r.goal_y = gy;
  r.goal_yaw = -90;
  r.planner = planner;
  r.time_budget = 2.0;
  return r;
}

// The waypoints, back in the map's cells, must be free on the map inflated
// by the radius (checked cell by cell).
void expectCollisionFree(const bp::ObstacleCells& cells, const beft::plan_result_t& result, double radius_m) {
  bp::GridMap grid(cells.width, cells.height);
  for (int y = 0; y < cells.height; ++y) {
    for (int x = 0; x < cells.width; ++x) grid.setBlocked(x, y, cells.at(x, y) == kOccupied);
  }
  const bp::PlanningMap map(grid, radius_m / cells.resolution);
  bp::Path path;
  for (const auto& w : result.waypoints) {
    path.push_back({(w.x - cells.origin_x) / cells.resolution, (w.y - cells.origin_y) / cells.resolution});
  }
  EXPECT_EQ(bp::test::findCollision(map.inflated(), path), "");
}

TEST(PlannerService, PlansAroundTheSeenWallInWorldMetres) {
  PlannerService service(ServiceConfig{});
  const auto cells = wallWorld();
  service.setObstacleMap(bp::makeObstacleMap(cells, beft::obstacle_map_t::ENCODING_RLE));
  for (const std::string planner : {"pf", "pf-geodesic", "astar", "ompl:RRTConnect"}) {
    SCOPED_TRACE(planner);
    const auto result = service.handle(request(planner.size(), 0.0, 3.0, 5.5, 3.0, planner), 42);
    ASSERT_TRUE(result.has_value());
    ASSERT_TRUE(result->success) << result->message;
    EXPECT_EQ(result->planner, planner);
    EXPECT_EQ(result->utime, 42);
    EXPECT_EQ(result->num_waypoints, static_cast<int32_t>(result->waypoints.size()));
    ASSERT_GE(result->waypoints.size(), 3u);  // it must turn round the wall's end
    EXPECT_NEAR(result->waypoints.front().x, 0.0, 1e-9);
    EXPECT_NEAR(result->waypoints.back().x, 5.5, 1e-9);
    EXPECT_NEAR(result->waypoints.back().y, 3.0, 1e-9);
    EXPECT_DOUBLE_EQ(result->waypoints.back().yaw, -90.0);  // the goal heading
    // Headings are the directions of travel out of each waypoint, in degrees.
    for (size_t i = 0; i + 1 < result->waypoints.size(); ++i) {
      const auto& a = result->waypoints[i];
      const auto& b = result->waypoints[i + 1];
      EXPECT_NEAR(a.yaw, std::atan2(b.y - a.y, b.x - a.x) * 180 / M_PI, 1e-6);
    }
    // The path passes above the wall's end (5.5 m) plus the robot radius.
    double highest = 0, length = 0;
    for (size_t i = 0; i < result->waypoints.size(); ++i) {
      highest = std::max(highest, result->waypoints[i].y);
      if (i > 0) length += std::hypot(result->waypoints[i].x - result->waypoints[i - 1].x,
                                      result->waypoints[i].y - result->waypoints[i - 1].y);
    }
    EXPECT_GT(highest, 5.5 + 0.35);
    EXPECT_NEAR(result->length, length, 1e-6);
    expectCollisionFree(cells, *result, 0.35);
  }
}

TEST(PlannerService, UnknownCellsCountAsFree) {
  PlannerService service(ServiceConfig{});
  service.setObstacleMap(bp::makeObstacleMap(wallWorld(), beft::obstacle_map_t::ENCODING_RAW));
  // Start and goal in the unknown right half: a straight line.
  const auto result = service.handle(request(1, 4.0, 2.0, 7.0, 6.0, "astar"), 0);
  ASSERT_TRUE(result && result->success) << result->message;
  EXPECT_EQ(result->waypoints.size(), 2u);
  EXPECT_NEAR(result->length, 5.0, 1e-9);
}

TEST(PlannerService, AnswersEachRequestIdOnce) {
  PlannerService service(ServiceConfig{});
  service.setObstacleMap(bp::makeObstacleMap(wallWorld(), beft::obstacle_map_t::ENCODING_RLE));
  EXPECT_TRUE(service.handle(request(7, 0, 3, 1, 3), 0).has_value());
  EXPECT_FALSE(service.handle(request(7, 0, 3, 1, 3), 0).has_value());
  EXPECT_TRUE(service.handle(request(8, 0, 3, 1, 3), 0).has_value());
}

TEST(PlannerService, BadRequestsFailWithAMessage) {
  PlannerService service(ServiceConfig{});
  service.setObstacleMap(bp::makeObstacleMap(wallWorld(), beft::obstacle_map_t::ENCODING_RLE));
  const auto expect_failure = [&](const beft::plan_request_t& r, const std::string& fragment) {
    const auto result = service.handle(r, 0);
    ASSERT_TRUE(result.has_value());
    EXPECT_FALSE(result->success);
    EXPECT_EQ(result->num_waypoints, 0);
    EXPECT_NE(result->message.find(fragment), std::string::npos) << result->message;
  };
  expect_failure(request(1, 0, 3, 20, 3), "goal (20.00, 3.00) is outside the obstacle map");
  expect_failure(request(2, -5, 3, 1, 3), "start (-5.00, 3.00) is outside");
  expect_failure(request(3, 0, 3, 3.1, 3.0), "goal (3.10, 3.00) is blocked");
  expect_failure(request(4, 0, 3, 1, 3, "dijkstra"), "unknown planner 'dijkstra'");
  expect_failure(request(5, NAN, 3, 1, 3), "non-finite");
}

TEST(PlannerService, StartCloseToAnObstacleMovesClearFirst) {
  PlannerService service(ServiceConfig{});
  service.setObstacleMap(bp::makeObstacleMap(wallWorld(), beft::obstacle_map_t::ENCODING_RLE));
  // 0.15 m from the wall's face: within the 0.35 m radius.
  const auto result = service.handle(request(1, 2.85, 2.0, 0.0, 2.0, "astar"), 0);
  ASSERT_TRUE(result && result->success) << result->message;
  EXPECT_NE(result->message.find("start within the robot radius"), std::string::npos);
  EXPECT_NEAR(result->waypoints.front().x, 2.85, 1e-9);
  EXPECT_LT(result->waypoints[1].x, 2.85);  // first away from the wall
}

TEST(PlannerService, WithoutAMapPlansTheStraightLine) {
  PlannerService service(ServiceConfig{});
  const auto result = service.handle(request(1, 0, 0, 3, 4), 0);
  ASSERT_TRUE(result && result->success);
  EXPECT_EQ(result->waypoints.size(), 2u);
  EXPECT_NEAR(result->length, 5.0, 1e-12);
  EXPECT_NE(result->message.find("no obstacle map"), std::string::npos);
}

TEST(PlannerService, RefusesUnknownDefaultPlannerAndMalformedMaps) {
  ServiceConfig config;
  config.default_planner = "bogus";
  EXPECT_THROW(PlannerService{config}, std::invalid_argument);
  PlannerService service(ServiceConfig{});
  auto bad = bp::makeObstacleMap(wallWorld(), beft::obstacle_map_t::ENCODING_RLE);
  bad.data_size = 3;
  EXPECT_THROW(service.setObstacleMap(bad), bp::ObstacleMapError);
  EXPECT_FALSE(service.hasMap());
}

TEST(PlannerService, SameRequestSameAnswerAcrossServices) {
  const auto answer = [] {
    PlannerService service(ServiceConfig{});
    service.setObstacleMap(bp::makeObstacleMap(wallWorld(), beft::obstacle_map_t::ENCODING_RLE));
    return *service.handle(request(3, 0.0, 3.0, 5.5, 3.0, "pf"), 0);
  };
  const auto a = answer(), b = answer();
  ASSERT_TRUE(a.success);
  ASSERT_EQ(a.waypoints.size(), b.waypoints.size());
  for (size_t i = 0; i < a.waypoints.size(); ++i) {
    EXPECT_EQ(a.waypoints[i].x, b.waypoints[i].x);
    EXPECT_EQ(a.waypoints[i].y, b.waypoints[i].y);
  }
}

// The real process on its own UDP port: a map and a request in, one result out.
TEST(PlannerServiceProcess, AnswersARequestOverLcm) {
  const int port = 40000 + static_cast<int>(getpid() % 20000);  // a range of its own
  const std::string url = "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good());
  struct Results {
    std::vector<beft::plan_result_t> received;
    void on(const lcm::ReceiveBuffer*, const std::string&, const beft::plan_result_t* msg) { received.push_back(*msg); }
  } results;
  lcm.subscribe("PLAN_RESULT", &Results::on, &results);

  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    execl(BEFT_PLANNER_BINARY, BEFT_PLANNER_BINARY, "--lcm-url", url.c_str(), "--planner", "pf-geodesic",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto map = bp::makeObstacleMap(wallWorld(), beft::obstacle_map_t::ENCODING_RLE);
  auto req = request(11, 0.0, 3.0, 5.5, 3.0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  // Re-send until answered: the process may still be starting; it answers id 11 once.
  while (results.received.empty() && std::chrono::steady_clock::now() < deadline) {
    lcm.publish("OBSTACLE_MAP", &map);
    lcm.publish("PLAN_REQUEST", &req);
    lcm.handleTimeout(300);
  }
  // A later request's answer comes after any second answer to id 11.
  const auto later = request(12, 0.0, 3.0, 5.5, 3.0);
  lcm.publish("PLAN_REQUEST", &later);
  const auto answered_later = [&results] {
    return std::any_of(results.received.begin(), results.received.end(),
                       [](const beft::plan_result_t& r) { return r.request_id == 12; });
  };
  while (!answered_later() && std::chrono::steady_clock::now() < deadline + std::chrono::seconds(20))
    lcm.handleTimeout(300);
  kill(child, SIGTERM);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(answered_later());
  ASSERT_EQ(results.received.size(), 2u) << "request 11 answered more than once";
  const auto& result = results.received.front();
  EXPECT_EQ(result.request_id, 11);
  EXPECT_TRUE(result.success) << result.message;
  EXPECT_EQ(result.planner, "pf-geodesic");
  EXPECT_NEAR(result.waypoints.back().x, 5.5, 1e-9);
  expectCollisionFree(wallWorld(), result, 0.35);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

// A request is planned on the map of its tick, even when a newer one has
// arrived by the time the planner gets to it (in lockstep the next ticks
// run on while the request waits: which map would be newest then depends on
// the machine's load).
TEST(PlannerServiceProcess, PlansEachRequestOnTheMapOfItsTime) {
  const int port = 40000 + static_cast<int>((getpid() + 7919) % 20000);
  const std::string url = "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good());
  struct Results {
    std::map<int64_t, beft::plan_result_t> received;
    void on(const lcm::ReceiveBuffer*, const std::string&, const beft::plan_result_t* msg) {
      received[msg->request_id] = *msg;
    }
  } results;
  lcm.subscribe("PLAN_RESULT", &Results::on, &results);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    execl(BEFT_PLANNER_BINARY, BEFT_PLANNER_BINARY, "--lcm-url", url.c_str(), "--planner", "astar",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Tick 10: the wall; tick 20: the wall gone.
  bp::ObstacleCells open = wallWorld();
  for (auto& cell : open.cells) cell = kFree;
  const auto walled_map = bp::makeObstacleMap(wallWorld(), beft::obstacle_map_t::ENCODING_RLE, 1'000'000, 10);
  const auto open_map = bp::makeObstacleMap(open, beft::obstacle_map_t::ENCODING_RLE, 2'000'000, 20);
  auto at_tick_10 = request(21, 0.0, 3.0, 5.5, 3.0);
  at_tick_10.utime = 1'000'000;
  auto at_tick_20 = request(22, 0.0, 3.0, 5.5, 3.0);
  at_tick_20.utime = 2'000'000;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (results.received.size() < 2 && std::chrono::steady_clock::now() < deadline) {
    lcm.publish("OBSTACLE_MAP", &walled_map);
    lcm.publish("OBSTACLE_MAP", &open_map);
    lcm.publish("PLAN_REQUEST", &at_tick_10);
    lcm.publish("PLAN_REQUEST", &at_tick_20);
    lcm.handleTimeout(300);
  }
  kill(child, SIGTERM);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_EQ(results.received.size(), 2u);
  const auto& around = results.received.at(21);
  const auto& straight = results.received.at(22);
  ASSERT_TRUE(around.success && straight.success) << around.message << straight.message;
  EXPECT_NEAR(straight.length, 5.5, 0.05);
  EXPECT_GT(around.length, 8.0);  // over the wall's end at y = 5.5 m and back
  expectCollisionFree(wallWorld(), around, 0.35);
}

}  // namespace
}  // namespace beft::planner_service

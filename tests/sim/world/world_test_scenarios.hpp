// Small scenarios built by hand for the world's tests.
#pragma once

#include <string>

#include "lib/scenario/scenario.hpp"

namespace beft::world::testing {

inline scenario::Object boxObject(const std::string& id, const std::string& label, double x, double y, double yaw,
                                  double size_x, double size_y, double size_z) {
  scenario::Object object;
  object.id = id;
  object.label = label;
  object.x = x;
  object.y = y;
  object.yaw = yaw;
  scenario::Visual visual;
  visual.shape = scenario::Visual::Shape::Box;
  visual.size_x = size_x;
  visual.size_y = size_y;
  visual.size_z = size_z;
  object.visual = visual;
  return object;
}

inline scenario::Object personObject(const std::string& id, double x, double y) {
  scenario::Object object;
  object.id = id;
  object.label = "person";
  object.x = x;
  object.y = y;
  scenario::Visual visual;
  visual.shape = scenario::Visual::Shape::Cylinder;
  visual.radius = 0.3;
  visual.height = 1.8;
  visual.color_rgb = 0xd04040;
  object.visual = visual;
  return object;
}

// A 30 x 20 m yard, robot at (2, 2) facing +x, default limits.
inline scenario::Scenario emptyYard() {
  scenario::Scenario scenario;
  scenario.name = "test_yard";
  scenario.dt = 0.1;
  scenario.duration = 60;
  scenario.world.width = 30;
  scenario.world.height = 20;
  scenario.categories = {"person", "car", "siren", "wall", "fire"};
  scenario.robot.x = 2;
  scenario.robot.y = 2;
  return scenario;
}

}  // namespace beft::world::testing

// Scenario objects for tests: a box of a given size resting on z, and a
// cylinder, without loading a file.
#pragma once

#include <string>

#include "lib/scenario/scenario.hpp"

namespace beft::scenario::test_objects {

inline Object solid(const std::string& id, const std::string& label, double x, double y, double sx, double sy,
                    double sz, double z = 0) {
  Object object;
  object.id = id;
  object.label = label;
  object.x = x;
  object.y = y;
  object.z = z;
  object.visual = Visual{};
  object.visual->size_x = sx;
  object.visual->size_y = sy;
  object.visual->size_z = sz;
  return object;
}

inline Object cylinder(const std::string& id, const std::string& label, double x, double y, double radius,
                       double height) {
  Object object = solid(id, label, x, y, 0, 0, 0);
  object.visual->shape = Visual::Shape::Cylinder;
  object.visual->radius = radius;
  object.visual->height = height;
  return object;
}

}  // namespace beft::scenario::test_objects

// Hand-made ground truth for the expert tests: scene objects, scenes and
// robot states as the world would publish them.
#pragma once

#include <string>
#include <vector>

#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

namespace beft::test {

inline scene_object_t pointObject(const std::string& id, const std::string& label, double x, double y,
                                  double z = 0) {
  scene_object_t o{};
  o.id = id;
  o.label = label;
  o.activity = "idle";
  o.x = x;
  o.y = y;
  o.z = z;
  o.shape = scene_object_t::SHAPE_NONE;
  o.acoustic_label = "";
  o.sound = "";
  o.level = 1.0;
  return o;
}

inline scene_object_t boxObject(const std::string& id, const std::string& label, double x, double y, double yaw,
                                double size_x, double size_y, double size_z) {
  scene_object_t o = pointObject(id, label, x, y);
  o.yaw = yaw;
  o.shape = scene_object_t::SHAPE_BOX;
  o.size_x = size_x;
  o.size_y = size_y;
  o.size_z = size_z;
  return o;
}

inline scene_object_t cylinderObject(const std::string& id, const std::string& label, double x, double y,
                                     double radius, double height) {
  scene_object_t o = pointObject(id, label, x, y);
  o.shape = scene_object_t::SHAPE_CYLINDER;
  o.radius = radius;
  o.size_x = o.size_y = 2 * radius;
  o.size_z = height;
  return o;
}

// Makes an object sound now, with the label its sound suggests.
inline scene_object_t sounding(scene_object_t o, const std::string& activity, const std::string& acoustic_label = "") {
  o.has_acoustic = true;
  o.sound_active = true;
  o.activity = activity;
  o.acoustic_label = acoustic_label;
  o.sound = "sounds/test.wav";
  return o;
}

inline scene_objects_t scene(const std::vector<scene_object_t>& objects, int64_t tick = 0,
                             double world_width = 30, double world_height = 20) {
  scene_objects_t s{};
  s.tick = tick;
  s.utime = tick * 100000;
  s.world_width = world_width;
  s.world_height = world_height;
  s.scenario = "test";
  s.dt = 0.1;
  s.duration = 60;
  s.categories = {"person", "car", "siren", "wall", "fire"};
  s.num_categories = static_cast<int32_t>(s.categories.size());
  s.num_congruency = 0;
  s.objects = objects;
  for (auto& o : s.objects) o.utime = s.utime;
  s.num_objects = static_cast<int32_t>(s.objects.size());
  return s;
}

inline robot_state_t robot(double x, double y, double yaw, double head_yaw = 0, double head_pitch = 0,
                           int64_t tick = 0) {
  robot_state_t r{};
  r.tick = tick;
  r.utime = tick * 100000;
  r.x = x;
  r.y = y;
  r.yaw = yaw;
  r.head_yaw = head_yaw;
  r.head_pitch = head_pitch;
  r.radius = 0.35;
  r.camera_height = 1.6;
  r.last_command = "";
  return r;
}

}  // namespace beft::test

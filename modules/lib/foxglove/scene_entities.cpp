// The scene's entities, one kind each (scene_messages.hpp).
#include <algorithm>
#include <cstdio>

#include "lib/foxglove/foxglove_values.hpp"
#include "lib/foxglove/json_text.hpp"
#include "lib/foxglove/scene_messages.hpp"

namespace beft::foxglove {

namespace {

const nlohmann::json kLabelColor = color(1, 1, 1, 1);

nlohmann::json keyValue(const std::string& key, const std::string& value) {
  return {{"key", key}, {"value", validUtf8(value)}};
}

nlohmann::json objectEntity(const beft::scene_object_t& object, int64_t utime) {
  nlohmann::json entity = sceneEntity("object/" + object.id, utime);
  entity["metadata"] = {keyValue("label", object.label), keyValue("activity", object.activity),
                        keyValue("sound_active", object.sound_active ? "true" : "false")};
  const double height = std::max(object.size_z, 0.01);
  const nlohmann::json centre = pose(object.x, object.y, object.z + height / 2, object.yaw);
  const nlohmann::json paint = colorOfRgb(object.color_rgb);
  if (object.shape == beft::scene_object_t::SHAPE_CYLINDER) {
    const double diameter = object.radius > 0 ? 2 * object.radius : object.size_x;
    entity["cylinders"].push_back(cylinderPrimitive(centre, vector3(diameter, diameter, height), paint));
  } else if (object.shape == beft::scene_object_t::SHAPE_BOX) {
    entity["cubes"].push_back(cubePrimitive(centre, vector3(object.size_x, object.size_y, height), paint));
  } else {
    entity["spheres"].push_back(spherePrimitive(pose(object.x, object.y, object.z + 0.15), 0.3, paint));
  }
  if (object.label != "wall")
    entity["texts"].push_back(
        textPrimitive(pose(object.x, object.y, object.z + height + 0.3), object.id, 0.3, kLabelColor));
  return entity;
}

std::string hypothesisState(const beft::hypothesis_t& hypothesis) {
  if (hypothesis.verified) return "verified";
  if (hypothesis.falsified) return "falsified";
  if (hypothesis.seen && hypothesis.heard) return "seen+heard";
  if (hypothesis.heard) return "heard";
  if (hypothesis.seen) return "seen";
  return "";
}

std::string hypothesisLabel(const beft::hypothesis_t& hypothesis) {
  char confidence[32];
  std::snprintf(confidence, sizeof confidence, "%.2f", hypothesis.confidence);
  std::string label = hypothesis.best_category + " " + confidence;
  const std::string state = hypothesisState(hypothesis);
  return state.empty() ? label : label + " " + state;
}

}  // namespace

nlohmann::json sceneObjectEntities(const beft::scene_objects_t& objects) {
  nlohmann::json entities = nlohmann::json::array();
  for (const beft::scene_object_t& object : objects.objects) entities.push_back(objectEntity(object, objects.utime));
  return entities;
}

nlohmann::json robotEntity(const beft::robot_state_t& robot) {
  nlohmann::json entity = sceneEntity("robot", robot.utime);
  const double head_height = std::max(robot.camera_height, 0.3);
  const double body_height = head_height - 0.15;
  const double diameter = std::max(2 * robot.radius, 0.1);
  const nlohmann::json body_color = robot.collided ? color(0.9, 0.2, 0.2) : color(0.35, 0.4, 0.48);
  entity["cylinders"].push_back(cylinderPrimitive(pose(robot.x, robot.y, body_height / 2, robot.yaw),
                                                  vector3(diameter, diameter, body_height), body_color));
  entity["spheres"].push_back(spherePrimitive(pose(robot.x, robot.y, head_height), 0.22, color(0.85, 0.85, 0.85)));
  entity["arrows"].push_back(arrowPrimitive(pose(robot.x, robot.y, head_height, robot.yaw + robot.head_yaw,
                                                 robot.head_pitch),
                                            1.0, 0.04, color(1.0, 0.85, 0.1)));
  entity["metadata"] = {keyValue("last_command", robot.last_command),
                        keyValue("collisions", std::to_string(robot.collisions))};
  return entity;
}

nlohmann::json hypothesisColor(const beft::hypothesis_t& hypothesis) {
  if (hypothesis.verified) return color(0.1, 0.8, 0.2, 0.85);
  if (hypothesis.falsified) return color(0.55, 0.55, 0.55, 0.85);
  if (hypothesis.seen && hypothesis.heard) return color(1.0, 0.9, 0.1, 0.85);
  if (hypothesis.heard) return color(1.0, 0.55, 0.0, 0.85);
  if (hypothesis.seen) return color(0.2, 0.5, 1.0, 0.85);
  return color(1, 1, 1, 0.85);
}

nlohmann::json hypothesisEntities(const beft::hypotheses_t& hypotheses) {
  nlohmann::json entities = nlohmann::json::array();
  for (const beft::hypothesis_t& hypothesis : hypotheses.hypotheses) {
    nlohmann::json entity = sceneEntity("hypothesis/" + hypothesis.object_id, hypotheses.utime);
    entity["spheres"].push_back(
        spherePrimitive(pose(hypothesis.x, hypothesis.y, hypothesis.z), 0.4, hypothesisColor(hypothesis)));
    entity["texts"].push_back(textPrimitive(pose(hypothesis.x, hypothesis.y, hypothesis.z + 0.6),
                                            hypothesisLabel(hypothesis), 0.25, kLabelColor));
    entity["metadata"] = {keyValue("best_category", hypothesis.best_category),
                          keyValue("seen_as", hypothesis.seen_as), keyValue("heard_as", hypothesis.heard_as),
                          keyValue("located", hypothesis.located ? "true" : "false")};
    entities.push_back(std::move(entity));
  }
  return entities;
}

nlohmann::json heardEntities(const beft::acoustic_percepts_t& heard) {
  nlohmann::json entities = nlohmann::json::array();
  for (const beft::acoustic_percept_t& percept : heard.percepts) {
    nlohmann::json entity = sceneEntity("heard/" + percept.object_id, heard.utime);
    entity["spheres"].push_back(
        spherePrimitive(pose(percept.est_x, percept.est_y, percept.est_z), 0.6, color(0.7, 0.3, 0.9, 0.45)));
    entity["texts"].push_back(textPrimitive(pose(percept.est_x, percept.est_y, percept.est_z + 0.5),
                                            percept.acoustic_label, 0.22, color(0.85, 0.7, 1.0)));
    // A point along a bearing, not a crossing of bearings.
    entity["metadata"] = nlohmann::json::array({keyValue("located", percept.located ? "true" : "false")});
    entities.push_back(std::move(entity));
  }
  return entities;
}

nlohmann::json planEntity(const beft::plan_result_t& plan) {
  nlohmann::json entity = sceneEntity("plan", plan.utime);
  if (!plan.success) return entity;
  const nlohmann::json paint = color(0.1, 0.75, 1.0);
  nlohmann::json points = nlohmann::json::array();
  for (const beft::waypoint_t& waypoint : plan.waypoints) {
    entity["arrows"].push_back(arrowPrimitive(pose(waypoint.x, waypoint.y, 0.05, waypoint.yaw), 0.4, 0.04, paint));
    points.push_back(vector3(waypoint.x, waypoint.y, 0.05));
  }
  if (points.size() >= 2) entity["lines"].push_back(lineStripPrimitive(points, 0.03, paint));
  return entity;
}

}  // namespace beft::foxglove

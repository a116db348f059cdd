// beft messages in Foxglove's schemas: entity counts, colours and poses of
// a small hand-made scene, the transforms, the map as a grid, camera frames
// as raw images, log lines, and the Foxglove schemas they follow.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lib/camera/frame_compressor.hpp"
#include "lib/foxglove/scene_messages.hpp"
#include "lib/wire/obstacle_map_codec.hpp"

using namespace beft::foxglove;
using nlohmann::json;

namespace {

beft::scene_object_t object(const std::string& id, const std::string& label, int8_t shape, int32_t rgb) {
  beft::scene_object_t o{};
  o.id = id;
  o.label = label;
  o.shape = shape;
  o.x = 2;
  o.y = 3;
  o.z = 0;
  o.yaw = 90;
  o.size_x = 4;
  o.size_y = 0.2;
  o.size_z = 2;
  o.radius = shape == beft::scene_object_t::SHAPE_CYLINDER ? 0.3 : 0;
  o.color_rgb = rgb;
  return o;
}

beft::scene_objects_t smallScene() {
  beft::scene_objects_t scene{};
  scene.utime = 2500000;
  scene.objects = {object("wall_1", "wall", beft::scene_object_t::SHAPE_BOX, 0x808080),
                   object("person_1", "person", beft::scene_object_t::SHAPE_CYLINDER, 0xff0000)};
  scene.num_objects = 2;
  return scene;
}

beft::robot_state_t robot() {
  beft::robot_state_t state{};
  state.utime = 2500000;
  state.x = 1;
  state.y = -1;
  state.yaw = 90;
  state.head_yaw = 0;
  state.head_pitch = 0;
  state.radius = 0.3;
  state.camera_height = 1.5;
  return state;
}

beft::hypothesis_t hypothesis(const std::string& id, bool seen, bool heard, bool verified, bool falsified) {
  beft::hypothesis_t h{};
  h.object_id = id;
  h.x = 5;
  h.y = 6;
  h.best_category = "person";
  h.confidence = 0.5;
  h.seen = seen;
  h.heard = heard;
  h.verified = verified;
  h.falsified = falsified;
  return h;
}

const json& entityWithId(const json& update, const std::string& id) {
  for (const json& entity : update.at("entities"))
    if (entity.at("id") == id) return entity;
  throw std::runtime_error("no entity " + id);
}

json rgba(double r, double g, double b, double a) { return {{"r", r}, {"g", g}, {"b", b}, {"a", a}}; }

}  // namespace

TEST(FoxgloveScene, ObjectsAsBoxesAndCylindersInTheirColours) {
  const json entities = sceneObjectEntities(smallScene());
  ASSERT_EQ(entities.size(), 2u);
  const json& wall = entities.at(0);
  EXPECT_EQ(wall.at("id"), "object/wall_1");
  EXPECT_EQ(wall.at("frame_id"), "world");
  EXPECT_EQ(wall.at("timestamp"), json({{"sec", 2}, {"nsec", 500000000}}));
  ASSERT_EQ(wall.at("cubes").size(), 1u);
  EXPECT_TRUE(wall.at("texts").empty());  // no label on walls
  const json& cube = wall.at("cubes").at(0);
  EXPECT_EQ(cube.at("size"), json({{"x", 4.0}, {"y", 0.2}, {"z", 2.0}}));
  EXPECT_EQ(cube.at("pose").at("position"), json({{"x", 2.0}, {"y", 3.0}, {"z", 1.0}}));  // standing on the ground
  EXPECT_NEAR(cube.at("pose").at("orientation").at("z").get<double>(), std::sqrt(0.5), 1e-12);  // yaw 90
  EXPECT_NEAR(cube.at("pose").at("orientation").at("w").get<double>(), std::sqrt(0.5), 1e-12);
  const double grey = 128.0 / 255.0;
  EXPECT_EQ(cube.at("color"), rgba(grey, grey, grey, 1));

  const json& person = entities.at(1);
  ASSERT_EQ(person.at("cylinders").size(), 1u);
  EXPECT_EQ(person.at("cylinders").at(0).at("size"), json({{"x", 0.6}, {"y", 0.6}, {"z", 2.0}}));
  EXPECT_EQ(person.at("cylinders").at(0).at("color"), rgba(1, 0, 0, 1));
  EXPECT_EQ(person.at("texts").at(0).at("text"), "person_1");
}

TEST(FoxgloveScene, RobotBodyHeadAndGaze) {
  beft::robot_state_t state = robot();
  state.head_yaw = -90;
  state.head_pitch = 90;  // looking straight up
  const json entity = robotEntity(state);
  EXPECT_EQ(entity.at("id"), "robot");
  ASSERT_EQ(entity.at("cylinders").size(), 1u);
  ASSERT_EQ(entity.at("spheres").size(), 1u);
  ASSERT_EQ(entity.at("arrows").size(), 1u);
  EXPECT_EQ(entity.at("spheres").at(0).at("pose").at("position"), json({{"x", 1.0}, {"y", -1.0}, {"z", 1.5}}));
  // Gaze yaw 90 - 90 = 0, pitch up 90: the arrow's +x turns to +z, a rotation of -90 deg about +y.
  const json& q = entity.at("arrows").at(0).at("pose").at("orientation");
  EXPECT_NEAR(q.at("y").get<double>(), -std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(q.at("w").get<double>(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(q.at("x").get<double>(), 0, 1e-12);
  EXPECT_NEAR(q.at("z").get<double>(), 0, 1e-12);
  state.collided = true;
  EXPECT_EQ(robotEntity(state).at("cylinders").at(0).at("color").at("r"), 0.9);
}

TEST(FoxgloveScene, HypothesesColouredByState) {
  beft::hypotheses_t hypotheses{};
  hypotheses.utime = 1000;
  hypotheses.hypotheses = {hypothesis("a", true, true, true, false), hypothesis("b", true, true, false, true),
                           hypothesis("c", false, true, false, false), hypothesis("d", true, false, false, false),
                           hypothesis("e", true, true, false, false)};
  hypotheses.num_hypotheses = 5;
  const json entities = hypothesisEntities(hypotheses);
  ASSERT_EQ(entities.size(), 5u);
  const json expected[] = {rgba(0.1, 0.8, 0.2, 0.85), rgba(0.55, 0.55, 0.55, 0.85), rgba(1.0, 0.55, 0.0, 0.85),
                           rgba(0.2, 0.5, 1.0, 0.85), rgba(1.0, 0.9, 0.1, 0.85)};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(entities.at(i).at("spheres").at(0).at("color"), expected[i]) << i;
  EXPECT_EQ(entities.at(0).at("id"), "hypothesis/a");
  EXPECT_EQ(entities.at(0).at("texts").at(0).at("text"), "person 0.50 verified");
  EXPECT_EQ(entities.at(2).at("texts").at(0).at("text"), "person 0.50 heard");
}

TEST(FoxgloveScene, UpdateCombinesEveryKindAndReplacesTheOldScene) {
  const beft::scene_objects_t scene = smallScene();
  const beft::robot_state_t state = robot();
  beft::hypotheses_t hypotheses{};
  hypotheses.utime = 2400000;
  hypotheses.hypotheses = {hypothesis("person_1", false, true, false, false)};
  hypotheses.num_hypotheses = 1;
  beft::acoustic_percepts_t heard{};
  heard.utime = 2400000;
  beft::acoustic_percept_t percept{};
  percept.object_id = "person_1";
  percept.est_x = 7;
  percept.acoustic_label = "scream";
  heard.percepts = {percept};
  heard.num_percepts = 1;
  beft::plan_result_t plan{};
  plan.utime = 2600000;
  plan.success = true;
  plan.waypoints = {{}, {}, {}};
  plan.waypoints[1].x = 1;
  plan.waypoints[2].x = 2;
  plan.waypoints[2].yaw = 180;
  plan.num_waypoints = 3;

  SceneState inputs;
  inputs.objects = &scene;
  inputs.robot = &state;
  inputs.hypotheses = &hypotheses;
  inputs.heard = &heard;
  inputs.plan = &plan;
  const json update = sceneUpdate(inputs);
  EXPECT_EQ(update.at("entities").size(), 2u + 1u + 1u + 1u + 1u);
  ASSERT_EQ(update.at("deletions").size(), 1u);
  EXPECT_EQ(update.at("deletions").at(0).at("type"), 1);  // ALL older than the newest input
  EXPECT_EQ(update.at("deletions").at(0).at("timestamp"), json({{"sec", 2}, {"nsec", 600000000}}));
  const json& path = entityWithId(update, "plan");
  EXPECT_EQ(path.at("arrows").size(), 3u);
  EXPECT_EQ(path.at("lines").at(0).at("points").size(), 3u);
  EXPECT_NEAR(path.at("arrows").at(2).at("pose").at("orientation").at("z").get<double>(), 1.0, 1e-12);  // yaw 180
  EXPECT_EQ(entityWithId(update, "heard/person_1").at("texts").at(0).at("text"), "scream");
  EXPECT_EQ(entityWithId(update, "heard/person_1").at("metadata").at(0), json({{"key", "located"}, {"value", "false"}}));

  plan.success = false;
  EXPECT_TRUE(planEntity(plan).at("arrows").empty());
  SceneState only_robot;
  only_robot.robot = &state;
  only_robot.replace_all = false;
  const json small = sceneUpdate(only_robot);
  EXPECT_EQ(small.at("entities").size(), 1u);
  EXPECT_TRUE(small.at("deletions").empty());
}

TEST(FoxgloveScene, TransformsWorldToBaseToHead) {
  beft::robot_state_t state = robot();
  state.head_yaw = 180;
  const json transforms = frameTransforms(state).at("transforms");
  ASSERT_EQ(transforms.size(), 2u);
  EXPECT_EQ(transforms.at(0).at("parent_frame_id"), "world");
  EXPECT_EQ(transforms.at(0).at("child_frame_id"), "base_link");
  EXPECT_EQ(transforms.at(0).at("translation"), json({{"x", 1.0}, {"y", -1.0}, {"z", 0.0}}));
  EXPECT_EQ(transforms.at(1).at("parent_frame_id"), "base_link");
  EXPECT_EQ(transforms.at(1).at("child_frame_id"), "head");
  EXPECT_EQ(transforms.at(1).at("translation").at("z"), 1.5);
  EXPECT_NEAR(transforms.at(1).at("rotation").at("z").get<double>(), 1.0, 1e-12);
}

TEST(FoxgloveScene, ObstacleMapAsAnOccupancyGrid) {
  beft::planners::ObstacleCells cells;
  cells.width = 3;
  cells.height = 2;
  cells.resolution = 0.5;
  cells.origin_x = -1;
  cells.origin_y = 2;
  cells.cells = {beft::obstacle_map_t::CELL_FREE, beft::obstacle_map_t::CELL_OCCUPIED,
                 beft::obstacle_map_t::CELL_UNKNOWN, beft::obstacle_map_t::CELL_FREE,
                 beft::obstacle_map_t::CELL_FREE, beft::obstacle_map_t::CELL_OCCUPIED};
  const json grid =
      occupancyGrid(beft::planners::makeObstacleMap(cells, beft::obstacle_map_t::ENCODING_RLE_ZSTD, 3000000));
  EXPECT_EQ(grid.at("column_count"), 3);
  EXPECT_EQ(grid.at("row_stride"), 3);
  EXPECT_EQ(grid.at("cell_stride"), 1);
  EXPECT_EQ(grid.at("cell_size"), json({{"x", 0.5}, {"y", 0.5}}));
  EXPECT_EQ(grid.at("pose").at("position"), json({{"x", -1.0}, {"y", 2.0}, {"z", 0.0}}));
  EXPECT_EQ(grid.at("fields").at(0).at("type"), 2);  // INT8
  EXPECT_EQ(grid.at("data"), "AGT/AABk");            // 0, 100, -1, 0, 0, 100
  beft::obstacle_map_t broken = beft::planners::makeObstacleMap(cells, beft::obstacle_map_t::ENCODING_RAW);
  broken.data.pop_back();
  EXPECT_THROW(occupancyGrid(broken), std::runtime_error);
}

TEST(FoxgloveScene, CameraFramesAsRawImagesUnpackedFirst) {
  beft::camera_frame_t raw{};
  raw.utime = 40000;
  raw.encoding = beft::camera_frame_t::ENCODING_DEPTH_MM16;
  raw.width = 2;
  raw.height = 2;
  raw.data = {1, 0, 2, 0, 3, 0, 4, 0};
  raw.data_size = 8;
  beft::camera_frame_t packed;
  beft::camera::FrameCompressor compressor;
  compressor.compress(raw, packed);
  const json image = cameraImage(packed);
  EXPECT_EQ(image.at("encoding"), "16UC1");
  EXPECT_EQ(image.at("width"), 2);
  EXPECT_EQ(image.at("step"), 4);
  EXPECT_EQ(image.at("frame_id"), "camera");
  EXPECT_EQ(image.at("data"), "AQACAAMABAA=");
  raw.encoding = beft::camera_frame_t::ENCODING_RGB8;
  raw.data.assign(12, 9);
  raw.data_size = 12;
  EXPECT_EQ(cameraImage(raw).at("step"), 6);
  EXPECT_EQ(cameraImage(raw).at("encoding"), "rgb8");
  raw.data_size = 11;
  raw.data.pop_back();
  EXPECT_THROW(cameraImage(raw), std::runtime_error);
}

TEST(FoxgloveScene, LogLines) {
  const json line = logLine(1500000, beft::log::Level::Warn, "beft-world", "slow tick");
  EXPECT_EQ(line.at("level"), 3);  // WARNING
  EXPECT_EQ(line.at("name"), "beft-world");
  EXPECT_EQ(line.at("message"), "slow tick");
  EXPECT_EQ(line.at("timestamp"), json({{"sec", 1}, {"nsec", 500000000}}));
  EXPECT_EQ(logLine(0, beft::log::Level::Error, "p", "x").at("level"), 4);
}

// Every field a conversion writes is a property of its schema, recursively.
void expectFieldsInSchema(const json& value, const json& schema, const std::string& path) {
  if (schema.contains("oneOf")) return;  // an enumeration: a number
  const std::string type = schema.at("type");
  if (type == "object") {
    ASSERT_TRUE(value.is_object()) << path;
    for (const auto& [key, field] : value.items()) {
      ASSERT_TRUE(schema.at("properties").contains(key)) << path << "." << key;
      expectFieldsInSchema(field, schema.at("properties").at(key), path + "." + key);
    }
    for (const json& required : schema.at("required")) EXPECT_TRUE(value.contains(required)) << path << "." << required;
  } else if (type == "array") {
    ASSERT_TRUE(value.is_array()) << path;
    for (const json& item : value) expectFieldsInSchema(item, schema.at("items"), path + "[]");
  } else if (type == "string") {
    EXPECT_TRUE(value.is_string()) << path;
  } else if (type == "number" || type == "integer") {
    EXPECT_TRUE(value.is_number()) << path;
  } else if (type == "boolean") {
    EXPECT_TRUE(value.is_boolean()) << path;
  }
}

TEST(FoxgloveSchemas, WhatTheConversionsWriteFollowsTheirSchemas) {
  const beft::scene_objects_t scene = smallScene();
  const beft::robot_state_t state = robot();
  SceneState inputs;
  inputs.objects = &scene;
  inputs.robot = &state;
  expectFieldsInSchema(sceneUpdate(inputs), foxgloveSchema(kSceneUpdateSchema), "SceneUpdate");
  expectFieldsInSchema(frameTransforms(state), foxgloveSchema(kFrameTransformsSchema), "FrameTransforms");
  expectFieldsInSchema(frameTransforms(state).at("transforms").at(0), foxgloveSchema("foxglove.FrameTransform"),
                       "FrameTransform");
  expectFieldsInSchema(logLine(0, beft::log::Level::Info, "p", "m"), foxgloveSchema(kLogSchema), "Log");
  beft::planners::ObstacleCells cells;
  cells.width = 1;
  cells.height = 1;
  cells.cells = {beft::obstacle_map_t::CELL_FREE};
  expectFieldsInSchema(occupancyGrid(beft::planners::makeObstacleMap(cells, beft::obstacle_map_t::ENCODING_RAW)),
                       foxgloveSchema(kGridSchema), "Grid");
  EXPECT_EQ(foxgloveSchema(kGridSchema).at("properties").at("data").at("contentEncoding"), "base64");
  EXPECT_EQ(foxgloveSchema(kRawImageSchema).at("title"), "foxglove.RawImage");
  EXPECT_EQ(foxgloveSchema(kSceneUpdateSchema).at("properties").at("entities").at("items").at("properties")
                .at("timestamp").at("title"),
            "time");
  EXPECT_THROW(foxgloveSchema("foxglove.PointCloud"), std::invalid_argument);
}

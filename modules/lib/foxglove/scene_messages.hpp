// beft messages in Foxglove's own message schemas (encoding "json",
// schemaEncoding "jsonschema"), so Foxglove's 3-D, image and log panels show
// a run with no set-up: the scene as a foxglove.SceneUpdate, the robot's
// frames, the obstacle map as a foxglove.Grid, camera frames as
// foxglove.RawImage and process logs as foxglove.Log.
//
// Everything is in the fixed frame "world" (x east, y north, z up, metres),
// except the transforms world -> base_link -> head. Timestamps are the
// messages' utime (simulated time) as {sec, nsec}.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/camera_frame_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/obstacle_map_t.hpp>
#include <beft/plan_result_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "lib/common/log.hpp"

namespace beft::foxglove {

// Schema names of what this header makes (with foxgloveSchema below).
inline constexpr const char* kSceneUpdateSchema = "foxglove.SceneUpdate";
inline constexpr const char* kFrameTransformsSchema = "foxglove.FrameTransforms";
inline constexpr const char* kGridSchema = "foxglove.Grid";
inline constexpr const char* kRawImageSchema = "foxglove.RawImage";
inline constexpr const char* kLogSchema = "foxglove.Log";

inline constexpr const char* kWorldFrame = "world";
inline constexpr const char* kBaseFrame = "base_link";
inline constexpr const char* kHeadFrame = "head";
inline constexpr const char* kCameraFrame = "camera";

// --- the scene's entities, one kind each (foxglove.SceneEntity JSON) ---

// One entity per object, "object/<id>": a box or a cylinder in the object's
// colour standing on its base height (walls are boxes), its id as a label
// above it (not for walls); label and activity as metadata.
nlohmann::json sceneObjectEntities(const beft::scene_objects_t& objects);
// "robot": the platform as a cylinder (red after a collision), the head as a
// sphere at camera height and the gaze as an arrow along head yaw and pitch.
nlohmann::json robotEntity(const beft::robot_state_t& robot);
// One per hypothesis, "hypothesis/<object id>": a sphere coloured by its
// state (hypothesisColor) and a label "category confidence state".
nlohmann::json hypothesisEntities(const beft::hypotheses_t& hypotheses);
// One per heard source, "heard/<object id>": a translucent sphere at the
// acoustic estimate and its acoustic label.
nlohmann::json heardEntities(const beft::acoustic_percepts_t& heard);
// "plan": an arrow per waypoint along its heading and a line through them;
// no primitives when the plan failed.
nlohmann::json planEntity(const beft::plan_result_t& plan);

// {r, g, b, a} of a hypothesis: verified green, falsified grey, heard only
// orange, seen only blue, seen and heard (not settled) yellow, else white.
nlohmann::json hypothesisColor(const beft::hypothesis_t& hypothesis);

// The newest of each input, any of them absent (null).
struct SceneState {
  const beft::scene_objects_t* objects = nullptr;
  const beft::robot_state_t* robot = nullptr;
  const beft::hypotheses_t* hypotheses = nullptr;
  const beft::acoustic_percepts_t* heard = nullptr;
  const beft::plan_result_t* plan = nullptr;
  // Start with a deletion of every entity older than the newest input, so
  // that a hypothesis or object no longer listed disappears.
  bool replace_all = true;
};

// foxglove.SceneUpdate of every entity of the inputs present.
nlohmann::json sceneUpdate(const SceneState& state);

// foxglove.FrameTransforms: world -> base_link (platform position and yaw)
// and base_link -> head (camera height, head yaw and pitch).
nlohmann::json frameTransforms(const beft::robot_state_t& robot);

// foxglove.Grid of the map in world, one INT8 field "occupancy" per cell in
// the values of a ROS occupancy grid (free 0, occupied 100, unknown -1) so
// Foxglove's "map" colour mode draws it. Throws planners::ObstacleMapError
// (a std::runtime_error) for a malformed map.
nlohmann::json occupancyGrid(const beft::obstacle_map_t& map);

// foxglove.RawImage of a camera frame in frame "camera", unpacked first
// (the wire's zstd is no image format Foxglove knows): RGB8 as "rgb8",
// DEPTH_MM16 as "16UC1" (millimetres), INSTANCE16 as "mono16". Throws
// std::runtime_error with the reason when the frame is refused
// (lib/camera/frame_decoding.hpp).
nlohmann::json cameraImage(const beft::camera_frame_t& frame);

// foxglove.Log of one line of a process's log.
nlohmann::json logLine(int64_t utime, beft::log::Level level, const std::string& process, const std::string& text);

// The JSON Schema of kSceneUpdateSchema, kFrameTransformsSchema,
// "foxglove.FrameTransform", kGridSchema, kRawImageSchema or kLogSchema, as
// Foxglove publishes the message definitions; std::invalid_argument for
// another name.
nlohmann::json foxgloveSchema(const std::string& schema_name);

}  // namespace beft::foxglove

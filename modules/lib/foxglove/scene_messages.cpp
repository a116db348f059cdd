// The scene update, transforms, map, camera image and log line
// (scene_messages.hpp).
#include "lib/foxglove/scene_messages.hpp"

#include <algorithm>
#include <stdexcept>

#include "lib/camera/frame_decoding.hpp"
#include "lib/foxglove/foxglove_values.hpp"
#include "lib/foxglove/json_text.hpp"
#include "lib/wire/obstacle_map_codec.hpp"

namespace beft::foxglove {

namespace {

void append(nlohmann::json& entities, nlohmann::json more) {
  for (nlohmann::json& entity : more) entities.push_back(std::move(entity));
}

int64_t newestUtime(const SceneState& state) {
  int64_t newest = 0;
  if (state.objects) newest = std::max(newest, state.objects->utime);
  if (state.robot) newest = std::max(newest, state.robot->utime);
  if (state.hypotheses) newest = std::max(newest, state.hypotheses->utime);
  if (state.heard) newest = std::max(newest, state.heard->utime);
  if (state.plan) newest = std::max(newest, state.plan->utime);
  return newest;
}

nlohmann::json frameTransform(int64_t utime, const char* parent, const char* child, const nlohmann::json& translation,
                              const nlohmann::json& rotation) {
  return {{"timestamp", timeOf(utime)},
          {"parent_frame_id", parent},
          {"child_frame_id", child},
          {"translation", translation},
          {"rotation", rotation}};
}

// RawImage encoding of a camera_frame_t encoding.
const char* imageEncoding(int8_t encoding) {
  switch (encoding) {
    case beft::camera_frame_t::ENCODING_RGB8:
      return "rgb8";
    case beft::camera_frame_t::ENCODING_DEPTH_MM16:
      return "16UC1";
    case beft::camera_frame_t::ENCODING_INSTANCE16:
      return "mono16";
    default:
      throw std::runtime_error("camera frame encoding " + std::to_string(encoding) + " is unknown");
  }
}

}  // namespace

nlohmann::json sceneUpdate(const SceneState& state) {
  nlohmann::json deletions = nlohmann::json::array();
  if (state.replace_all)
    deletions.push_back({{"timestamp", timeOf(newestUtime(state))}, {"type", 1}, {"id", ""}});  // ALL
  nlohmann::json entities = nlohmann::json::array();
  if (state.objects) append(entities, sceneObjectEntities(*state.objects));
  if (state.robot) entities.push_back(robotEntity(*state.robot));
  if (state.hypotheses) append(entities, hypothesisEntities(*state.hypotheses));
  if (state.heard) append(entities, heardEntities(*state.heard));
  if (state.plan) entities.push_back(planEntity(*state.plan));
  return {{"deletions", deletions}, {"entities", entities}};
}

nlohmann::json frameTransforms(const beft::robot_state_t& robot) {
  const nlohmann::json base =
      frameTransform(robot.utime, kWorldFrame, kBaseFrame, vector3(robot.x, robot.y, 0), rotation(robot.yaw));
  const nlohmann::json head = frameTransform(robot.utime, kBaseFrame, kHeadFrame, vector3(0, 0, robot.camera_height),
                                             rotation(robot.head_yaw, robot.head_pitch));
  return {{"transforms", nlohmann::json::array({base, head})}};
}

nlohmann::json occupancyGrid(const beft::obstacle_map_t& map) {
  const planners::ObstacleCells cells = planners::decodeObstacleMap(map);
  std::string data(cells.cells.size(), '\0');
  for (std::size_t i = 0; i < cells.cells.size(); ++i) {
    const uint8_t cell = cells.cells[i];
    const int8_t occupancy = cell == beft::obstacle_map_t::CELL_OCCUPIED ? 100
                             : cell == beft::obstacle_map_t::CELL_FREE   ? 0
                                                                          : -1;
    data[i] = static_cast<char>(occupancy);
  }
  return {{"timestamp", timeOf(map.utime)},
          {"frame_id", kWorldFrame},
          {"pose", pose(cells.origin_x, cells.origin_y, 0)},
          {"column_count", cells.width},
          {"cell_size", {{"x", cells.resolution}, {"y", cells.resolution}}},
          {"row_stride", cells.width},
          {"cell_stride", 1},
          {"fields", nlohmann::json::array({{{"name", "occupancy"}, {"offset", 0}, {"type", 2}}})},  // INT8
          {"data", base64Encode(data)}};
}

nlohmann::json cameraImage(const beft::camera_frame_t& frame) {
  beft::camera_frame_t pixels;
  std::string why;
  if (!camera::decodeCameraFrame(frame, pixels, &why)) throw std::runtime_error("camera frame refused: " + why);
  const char* encoding = imageEncoding(pixels.encoding);
  const int64_t step = pixels.height > 0 ? static_cast<int64_t>(pixels.data.size()) / pixels.height : 0;
  return {{"timestamp", timeOf(pixels.utime)},
          {"frame_id", kCameraFrame},
          {"width", pixels.width},
          {"height", pixels.height},
          {"encoding", encoding},
          {"step", step},
          {"data", base64Encode(pixels.data.data(), pixels.data.size())}};
}

nlohmann::json logLine(int64_t utime, beft::log::Level level, const std::string& process, const std::string& text) {
  int foxglove_level = 0;  // UNKNOWN
  switch (level) {
    case beft::log::Level::Debug: foxglove_level = 1; break;
    case beft::log::Level::Info: foxglove_level = 2; break;
    case beft::log::Level::Warn: foxglove_level = 3; break;
    case beft::log::Level::Error: foxglove_level = 4; break;
  }
  return {{"timestamp", timeOf(utime)},
          {"level", foxglove_level},
          {"message", validUtf8(text)},
          {"name", validUtf8(process)},
          {"file", ""},
          {"line", 0}};
}

}  // namespace beft::foxglove

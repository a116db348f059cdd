#include "sim/ears/ear_signals.hpp"

#include <algorithm>
#include <cmath>

#include "lib/scene/acoustic_occlusion.hpp"
#include "lib/scene/object_geometry.hpp"

namespace beft::ears {
namespace {

int64_t sampleAt(int64_t utime, double sample_rate) {
  return static_cast<int64_t>(std::llround(static_cast<double>(utime) * sample_rate / 1e6));
}

hearing::HeadPose headPose(const robot_state_t& robot) {
  return {geometry::headCentre(robot), geometry::noseHeadingDeg(robot)};
}

// Where a source sounds from: a person's mouth, a siren's horn, ... all at
// the object's centre (half its height), as the other experts measure it.
Eigen::Vector3d soundPosition(const scene_object_t& object) { return geometry::objectCentre(object); }

}  // namespace

hearing::BlockRequest blockRequest(const scene_objects_t& scene, const camera::SceneGeometry& solids,
                                   const robot_state_t& robot, const robot_state_t* previous,
                                   hearing::SoundBank& sounds, double sample_rate, const EarsConfig& config) {
  hearing::BlockRequest request;
  const int64_t end = sampleAt(robot.utime, sample_rate);
  const int64_t start = previous != nullptr && previous->utime < robot.utime
                            ? sampleAt(previous->utime, sample_rate)
                            : std::max<int64_t>(0, end - static_cast<int64_t>(std::llround(config.first_block_s * sample_rate)));
  request.first_sample = start;
  request.num_samples = static_cast<int>(std::max<int64_t>(0, end - start));
  request.current = headPose(robot);
  request.previous = previous != nullptr ? headPose(*previous) : request.current;
  request.noise_seed = static_cast<uint64_t>(config.seed);
  request.noise_rms = config.noise_rms;

  struct Candidate {
    double loudness;
    hearing::RenderedSource source;
  };
  std::vector<Candidate> candidates;
  const Eigen::Vector3d left_ear = geometry::leftEar(robot);
  const Eigen::Vector3d right_ear = geometry::rightEar(robot);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const auto& object = scene.objects[i];
    if (!geometry::isSounding(object) || !(object.level > 0)) continue;
    const hearing::SourceSignal* signal = sounds.sound(object.sound);
    if (signal == nullptr) continue;
    hearing::RenderedSource source;
    source.signal = signal;
    source.position = soundPosition(object);
    source.level = object.level;
    source.room_owner = static_cast<int>(i);
    source.occlusion = audio::acousticOcclusion(solids, static_cast<int>(i), audio::sourceSamplePoints(object),
                                                left_ear, right_ear) / 100.0;
    const double distance = std::max(0.3, (source.position - request.current.centre).norm());
    candidates.push_back({object.level / distance, source});
  }
  // Loudest first; equal loudness keeps scene order (stable), so the choice is deterministic.
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.loudness > b.loudness; });
  if (static_cast<int>(candidates.size()) > config.max_sources) candidates.resize(config.max_sources);
  for (auto& candidate : candidates) request.sources.push_back(candidate.source);
  return request;
}

std::optional<EarsRoom> roomOfScenario(const scenario::Scenario& scenario, const hearing::HrirSet& hrirs,
                                       double sample_rate) {
  if (!scenario.acoustics) return std::nullopt;
  const scenario::Acoustics& acoustics = *scenario.acoustics;
  hearing::RoomSettings settings;
  settings.reflection_order = acoustics.reflection_order;
  settings.ground = acoustics.ground;
  settings.ground_absorption = acoustics.absorption;
  settings.t60_s = acoustics.reverberation;
  settings.seed = scenario.seed + 1;
  double top = 2.5;
  std::map<std::string, double> absorption;
  for (const scenario::Object& object : scenario.objects) {
    if (!object.visual) continue;
    const scenario::Visual& visual = *object.visual;
    top = std::max(top, object.z + (visual.shape == scenario::Visual::Shape::Box ? visual.size_z : visual.height));
    absorption[object.id] = visual.absorption.value_or(acoustics.absorption);
  }
  settings.volume_m3 = scenario.world.width * scenario.world.height * top;
  return EarsRoom{hearing::RoomModel({}, settings, hrirs, sample_rate), std::move(absorption), acoustics.absorption};
}

hearing::RoomModel roomOfTick(const EarsRoom& room, const scene_objects_t& scene, const camera::SceneGeometry& solids) {
  std::vector<hearing::ReflectingBox> boxes;
  boxes.reserve(solids.solids().size());
  for (const camera::Solid& solid : solids.solids()) {
    hearing::ReflectingBox box;
    box.x = solid.x;
    box.y = solid.y;
    box.z_min = solid.z_min;
    box.z_max = solid.z_max;
    if (solid.shape == camera::Solid::Shape::Box) {
      box.yaw_deg = std::atan2(solid.sin_yaw, solid.cos_yaw) * 180 / M_PI;
      box.size_x = 2 * solid.half_x;
      box.size_y = 2 * solid.half_y;
    } else {
      box.size_x = box.size_y = 2 * solid.radius;
    }
    box.owner = solid.object_index;
    box.absorption = room.default_absorption;
    if (solid.object_index >= 0 && solid.object_index < static_cast<int>(scene.objects.size())) {
      const auto found = room.absorption.find(scene.objects[static_cast<std::size_t>(solid.object_index)].id);
      if (found != room.absorption.end()) box.absorption = found->second;
    }
    boxes.push_back(box);
  }
  return room.base.rebuilt(std::move(boxes));
}

binaural_block_t blockMessage(const hearing::StereoBlock& block, const hearing::BlockRequest& request,
                              const robot_state_t& robot, double sample_rate) {
  binaural_block_t message{};
  message.utime = robot.utime;
  message.tick = robot.tick;
  message.sample_rate = static_cast<int32_t>(std::lround(sample_rate));
  message.first_sample = request.first_sample;
  message.head_x = request.current.centre.x();
  message.head_y = request.current.centre.y();
  message.head_yaw = request.current.yaw_deg;
  const std::size_t count = std::min(block.left.size(), block.right.size());
  float peak = 0;
  for (std::size_t i = 0; i < count; ++i) peak = std::max({peak, std::fabs(block.left[i]), std::fabs(block.right[i])});
  message.full_scale = peak > 0 && std::isfinite(peak) ? peak : 1.0;
  const double to_int = 32767.0 / message.full_scale;
  auto quantise = [&](float value) {
    const double scaled = std::isfinite(value) ? std::round(value * to_int) : 0.0;
    return static_cast<int16_t>(std::clamp(scaled, -32767.0, 32767.0));
  };
  message.num_samples = static_cast<int32_t>(count);
  message.left.resize(count);
  message.right.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    message.left[i] = quantise(block.left[i]);
    message.right[i] = quantise(block.right[i]);
  }
  return message;
}

}  // namespace beft::ears

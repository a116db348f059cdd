#include "audio_estimator.hpp"

#include "acoustic_occlusion.hpp"
#include "object_geometry.hpp"

namespace beft::audio {

acoustic_percepts_t estimateAudio(const scene_objects_t& scene, const camera::SceneGeometry& solids,
                                  const robot_state_t& robot, const AudioConfig& config) {
  acoustic_percepts_t out{};
  out.utime = scene.utime;
  out.tick = scene.tick;
  const Eigen::Vector3d left_ear = geometry::leftEar(robot);
  const Eigen::Vector3d right_ear = geometry::rightEar(robot);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const auto& object = scene.objects[i];
    if (!geometry::isSounding(object)) continue;
    acoustic_percept_t percept;
    percept.object_id = object.id;
    percept.occlusion =
        acousticOcclusion(solids, static_cast<int>(i), sourceSamplePoints(object), left_ear, right_ear);
    Eigen::Vector2d offset = Eigen::Vector2d::Zero();
    if (config.noise.enabled) {
      const double a_p = model::acousticPerceptibility(geometry::objectDistance(robot, object), percept.occlusion,
                                                       geometry::objectAzimuthDeg(robot, object), config.model);
      offset = positionNoise(config.noise, scene.tick, object.id, a_p);
    }
    percept.est_x = object.x + offset.x();
    percept.est_y = object.y + offset.y();
    percept.est_z = object.z;
    percept.acoustic_label = object.acoustic_label.empty() ? object.label : object.acoustic_label;
    percept.activity = object.activity;
    percept.level = object.level;
    out.percepts.push_back(percept);
  }
  out.num_percepts = static_cast<int32_t>(out.percepts.size());
  return out;
}

}  // namespace beft::audio

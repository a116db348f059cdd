#include "experts/audio/audio_estimator.hpp"

#include <atomic>

#include "lib/scene/acoustic_occlusion.hpp"
#include "lib/scene/object_geometry.hpp"

namespace beft::audio {

namespace {

// O_a of each of the objects (indices into scene.objects), in their order.
// The two threads take objects one at a time as they come.
std::vector<double> occlusionsOf(const scene_objects_t& scene, const camera::SceneGeometry& solids,
                                 const std::vector<std::size_t>& objects, const robot_state_t& robot,
                                 expert::HelperTask* helper) {
  const Eigen::Vector3d left_ear = geometry::leftEar(robot);
  const Eigen::Vector3d right_ear = geometry::rightEar(robot);
  std::vector<double> occlusion(objects.size(), 0.0);
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t k = next++; k < objects.size(); k = next++) {
      const std::size_t i = objects[k];
      occlusion[k] = acousticOcclusion(solids, static_cast<int>(i), sourceSamplePoints(scene.objects[i]), left_ear,
                                       right_ear);
    }
  };
  if (helper != nullptr && objects.size() > 1) {
    helper->start(work);
    expert::WaitOnExit helped(*helper);  // also when this thread throws
    work();
    helper->wait();
  } else {
    work();
  }
  return occlusion;
}

}  // namespace

acoustic_percepts_t estimateAudio(const scene_objects_t& scene, const camera::SceneGeometry& solids,
                                  const robot_state_t& robot, const AudioConfig& config,
                                  expert::HelperTask* helper) {
  acoustic_percepts_t out{};
  out.utime = scene.utime;
  out.tick = scene.tick;
  std::vector<std::size_t> sounding;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (geometry::isSounding(scene.objects[i])) sounding.push_back(i);
  const std::vector<double> occlusion = occlusionsOf(scene, solids, sounding, robot, helper);
  for (std::size_t k = 0; k < sounding.size(); ++k) {
    const auto& object = scene.objects[sounding[k]];
    acoustic_percept_t percept;
    percept.object_id = object.id;
    percept.occlusion = occlusion[k];
    Eigen::Vector2d offset = Eigen::Vector2d::Zero();
    if (config.noise.enabled) {
      const double a_p = model::acousticPerceptibility(geometry::objectDistance(robot, object), percept.occlusion,
                                                       geometry::objectAzimuthDeg(robot, object), config.model);
      offset = positionNoise(config.noise, scene.tick, object.id, a_p);
    }
    percept.est_x = object.x + offset.x();
    percept.est_y = object.y + offset.y();
    percept.est_z = object.z;
    percept.located = true;  // the simulator's position, with noise when asked
    percept.acoustic_label = object.acoustic_label.empty() ? object.label : object.acoustic_label;
    percept.activity = object.activity;
    percept.level = object.level;
    out.percepts.push_back(percept);
  }
  out.num_percepts = static_cast<int32_t>(out.percepts.size());
  return out;
}

}  // namespace beft::audio

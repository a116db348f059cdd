#include "experts/audio/heard_percepts.hpp"

#include "lib/scene/acoustic_occlusion.hpp"
#include "lib/scene/object_geometry.hpp"

namespace beft::audio {

acoustic_percepts_t heardPercepts(const scene_objects_t& scene, const camera::SceneGeometry& solids,
                                  const robot_state_t& robot, const HeardSources& heard) {
  acoustic_percepts_t out{};
  out.utime = scene.utime;
  out.tick = scene.tick;
  const Eigen::Vector3d left_ear = geometry::leftEar(robot);
  const Eigen::Vector3d right_ear = geometry::rightEar(robot);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const auto& object = scene.objects[i];
    if (!geometry::isSounding(object)) continue;
    const auto estimate = heard.estimate(object.id);
    if (!estimate) continue;
    scene_object_t where_heard = object;  // the source's shape, where it was heard
    where_heard.x = estimate->position.x();
    where_heard.y = estimate->position.y();
    acoustic_percept_t percept;
    percept.object_id = object.id;
    percept.occlusion =
        acousticOcclusion(solids, static_cast<int>(i), sourceSamplePoints(where_heard), left_ear, right_ear);
    percept.est_x = estimate->position.x();
    percept.est_y = estimate->position.y();
    percept.est_z = object.z;
    percept.located = estimate->triangulated;
    percept.acoustic_label = object.acoustic_label.empty() ? object.label : object.acoustic_label;
    percept.activity = object.activity;
    percept.level = object.level;
    out.percepts.push_back(percept);
  }
  out.num_percepts = static_cast<int32_t>(out.percepts.size());
  return out;
}

}  // namespace beft::audio

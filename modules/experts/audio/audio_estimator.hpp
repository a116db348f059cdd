// The low-level audio expert's logic: for every object that sounds now, its
// acoustic occlusion O_a (acoustic_occlusion.hpp), its position estimate
// p_hat (the true position, plus optional seeded noise), the label its sound
// suggests, its activity and level.
#pragma once

#include <beft/acoustic_percepts_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "lib/expert/helper_task.hpp"
#include "lib/model/model.hpp"
#include "experts/audio/position_noise.hpp"
#include "lib/scene/scene_geometry.hpp"

namespace beft::audio {

struct AudioConfig {
  PositionNoiseConfig noise;
  model::Parameters model;  // for a_P (eq. 2), which sets the noise spread
};

// solids: the scene's geometry built from the same message (camera::SceneGeometry::fromMessage).
// helper, if given, computes part of the occlusions meanwhile (the same
// percepts either way: each object's O_a depends on nothing else).
acoustic_percepts_t estimateAudio(const scene_objects_t& scene, const camera::SceneGeometry& solids,
                                  const robot_state_t& robot, const AudioConfig& config,
                                  expert::HelperTask* helper = nullptr);

}  // namespace beft::audio

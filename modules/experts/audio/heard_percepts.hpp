// The audio expert's percepts with --param acoustics=binaural: like
// estimateAudio (audio_estimator.hpp), but p_hat is what was heard
// (heard_sources.hpp) and O_a is computed for a source at p_hat. Objects not
// yet heard are not reported. The height of p_hat is the object's own: the
// impulse responses are of the horizontal plane only, so elevation is not
// heard.
#pragma once

#include <beft/acoustic_percepts_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "experts/audio/heard_sources.hpp"
#include "lib/scene/scene_geometry.hpp"

namespace beft::audio {

acoustic_percepts_t heardPercepts(const scene_objects_t& scene, const camera::SceneGeometry& solids,
                                  const robot_state_t& robot, const HeardSources& heard);

}  // namespace beft::audio

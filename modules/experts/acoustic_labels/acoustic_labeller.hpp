// The acoustic labelling expert's logic (mid level): for every sounding
// object of AUDIO, its acoustic perceptibility a_P (eq. 2) from d_i and
// alpha_i of GEOMETRY and the occlusion O_a of AUDIO, and the confidence L_j
// of every category k_j (eq. 3 with a_P) given the label its sound suggests
// (the acoustic label: a radio playing a voice sounds like a person).
#pragma once

#include <string>
#include <vector>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/geometry_percepts_t.hpp>
#include <beft/labels_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "model.hpp"

namespace beft::acoustic_labels {

struct AcousticLabelling {
  labels_t labels{};                    // one entry per acoustic percept that could be labelled
  std::vector<std::string> skipped;   // percepts left out, each with the reason
};

// Stamped with the audio percepts' utime and tick.
AcousticLabelling labelAcoustically(const scene_objects_t& scene, const geometry_percepts_t& geometry,
                                    const acoustic_percepts_t& audio, const model::Parameters& parameters);

}  // namespace beft::acoustic_labels

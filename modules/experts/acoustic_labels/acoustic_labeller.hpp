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

#include "lib/expert/id_index.hpp"
#include "lib/model/model.hpp"

namespace beft::acoustic_labels {

struct AcousticLabelling {
  labels_t labels{};                    // one entry per acoustic percept that could be labelled
  std::vector<std::string> skipped;   // percepts left out, each with the reason
};

// Labels tick after tick, keeping its indices and its result's storage.
class AcousticLabeller {
 public:
  // Stamped with the audio percepts' utime and tick; valid until the next call.
  const AcousticLabelling& label(const scene_objects_t& scene, const geometry_percepts_t& geometry,
                                 const acoustic_percepts_t& audio, const model::Parameters& parameters);

 private:
  expert::IdIndex<geometry_percept_t> geometry_by_id_;
  expert::IdIndex<scene_object_t> object_by_id_;
  AcousticLabelling result_;
};

// One tick's labels (AcousticLabeller::label once).
AcousticLabelling labelAcoustically(const scene_objects_t& scene, const geometry_percepts_t& geometry,
                                    const acoustic_percepts_t& audio, const model::Parameters& parameters);

}  // namespace beft::acoustic_labels

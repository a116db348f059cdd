// The visual labelling expert's logic (mid level): for every object the
// camera shows (visible pixels in VISION), its visual perceptibility v_P (eq. 1) from the distance d_i of
// GEOMETRY and the occlusion O_v of VISION, and the confidence L_j of every
// category k_j (eq. 3) given the object's true category.
#pragma once

#include <string>
#include <vector>

#include <beft/geometry_percepts_t.hpp>
#include <beft/labels_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/visual_percepts_t.hpp>

#include "lib/expert/id_index.hpp"
#include "lib/model/model.hpp"

namespace beft::visual_labels {

struct VisualLabelling {
  labels_t labels{};                    // one entry per shown object that could be labelled
  std::vector<std::string> skipped;   // percepts left out, each with the reason
};

// Labels tick after tick, keeping its indices and its result's storage.
class VisualLabeller {
 public:
  // Stamped with the vision percepts' utime and tick; valid until the next call.
  const VisualLabelling& label(const scene_objects_t& scene, const geometry_percepts_t& geometry,
                               const visual_percepts_t& vision, const model::Parameters& parameters);

 private:
  expert::IdIndex<geometry_percept_t> geometry_by_id_;
  expert::IdIndex<scene_object_t> object_by_id_;
  VisualLabelling result_;
};

// One tick's labels (VisualLabeller::label once).
VisualLabelling labelVisually(const scene_objects_t& scene, const geometry_percepts_t& geometry,
                              const visual_percepts_t& vision, const model::Parameters& parameters);

}  // namespace beft::visual_labels

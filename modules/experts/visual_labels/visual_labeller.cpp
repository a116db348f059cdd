#include "experts/visual_labels/visual_labeller.hpp"

namespace beft::visual_labels {

const VisualLabelling& VisualLabeller::label(const scene_objects_t& scene, const geometry_percepts_t& geometry,
                                             const visual_percepts_t& vision, const model::Parameters& parameters) {
  geometry_by_id_.rebuild(geometry.percepts, &geometry_percept_t::object_id);
  object_by_id_.rebuild(scene.objects, &scene_object_t::id);

  VisualLabelling& result = result_;
  result.skipped.clear();
  result.labels.utime = vision.utime;
  result.labels.tick = vision.tick;
  result.labels.modality = labels_t::MODALITY_VISUAL;
  std::size_t count = 0;  // entries written: those of earlier ticks are written over
  for (const auto& percept : vision.percepts) {
    // Only what the camera shows is labelled: fusion takes visual evidence
    // from visible pixels alone, and at hundreds of objects the rest (v_P 0)
    // was most of the message.
    if (percept.visible_pixels <= 0) continue;
    const geometry_percept_t* g = geometry_by_id_.find(percept.object_id);
    const scene_object_t* object = object_by_id_.find(percept.object_id);
    if (g == nullptr || object == nullptr) {
      result.skipped.push_back(percept.object_id + (g == nullptr ? ": not in GEOMETRY" : ": not in GT_OBJECTS"));
      continue;
    }
    if (count == result.labels.objects.size()) result.labels.objects.emplace_back();
    object_labels_t& entry = result.labels.objects[count++];
    entry.object_id = percept.object_id;
    entry.perceptibility = model::visualPerceptibility(g->distance, percept.occlusion);  // eq. 1
    entry.categories = scene.categories;
    model::labelConfidences(scene.categories, object->label, entry.perceptibility, parameters,  // eq. 3
                            entry.confidence);
    entry.num_categories = static_cast<int32_t>(entry.categories.size());
  }
  result.labels.objects.resize(count);
  result.labels.num_objects = static_cast<int32_t>(count);
  return result;
}

VisualLabelling labelVisually(const scene_objects_t& scene, const geometry_percepts_t& geometry,
                              const visual_percepts_t& vision, const model::Parameters& parameters) {
  VisualLabeller labeller;
  return labeller.label(scene, geometry, vision, parameters);
}

}  // namespace beft::visual_labels

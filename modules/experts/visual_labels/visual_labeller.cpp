#include "visual_labeller.hpp"

#include <unordered_map>

namespace beft::visual_labels {

VisualLabelling labelVisually(const scene_objects_t& scene, const geometry_percepts_t& geometry,
                              const visual_percepts_t& vision, const model::Parameters& parameters) {
  std::unordered_map<std::string, const geometry_percept_t*> geometry_by_id;
  for (const auto& percept : geometry.percepts) geometry_by_id[percept.object_id] = &percept;
  std::unordered_map<std::string, const scene_object_t*> object_by_id;
  for (const auto& object : scene.objects) object_by_id[object.id] = &object;

  VisualLabelling result;
  result.labels.utime = vision.utime;
  result.labels.tick = vision.tick;
  result.labels.modality = labels_t::MODALITY_VISUAL;
  for (const auto& percept : vision.percepts) {
    // Only what the camera shows is labelled: fusion takes visual evidence
    // from visible pixels alone, and at hundreds of objects the rest (v_P 0)
    // was most of the message.
    if (percept.visible_pixels <= 0) continue;
    const auto geometry_it = geometry_by_id.find(percept.object_id);
    const auto object_it = object_by_id.find(percept.object_id);
    if (geometry_it == geometry_by_id.end() || object_it == object_by_id.end()) {
      result.skipped.push_back(percept.object_id + (geometry_it == geometry_by_id.end()
                                                        ? ": not in GEOMETRY"
                                                        : ": not in GT_OBJECTS"));
      continue;
    }
    object_labels_t entry;
    entry.object_id = percept.object_id;
    entry.perceptibility = model::visualPerceptibility(geometry_it->second->distance, percept.occlusion);  // eq. 1
    entry.categories = scene.categories;
    entry.confidence = model::labelConfidences(scene.categories, object_it->second->label,  // eq. 3
                                               entry.perceptibility, parameters);
    entry.num_categories = static_cast<int32_t>(entry.categories.size());
    result.labels.objects.push_back(std::move(entry));
  }
  result.labels.num_objects = static_cast<int32_t>(result.labels.objects.size());
  return result;
}

}  // namespace beft::visual_labels

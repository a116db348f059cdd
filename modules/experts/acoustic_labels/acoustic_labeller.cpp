#include "acoustic_labeller.hpp"

#include <unordered_map>

namespace beft::acoustic_labels {

AcousticLabelling labelAcoustically(const scene_objects_t& scene, const geometry_percepts_t& geometry,
                                    const acoustic_percepts_t& audio, const model::Parameters& parameters) {
  std::unordered_map<std::string, const geometry_percept_t*> geometry_by_id;
  for (const auto& percept : geometry.percepts) geometry_by_id[percept.object_id] = &percept;
  std::unordered_map<std::string, const scene_object_t*> object_by_id;
  for (const auto& object : scene.objects) object_by_id[object.id] = &object;

  AcousticLabelling result;
  result.labels.utime = audio.utime;
  result.labels.tick = audio.tick;
  result.labels.modality = labels_t::MODALITY_ACOUSTIC;
  for (const auto& percept : audio.percepts) {
    const auto geometry_it = geometry_by_id.find(percept.object_id);
    if (geometry_it == geometry_by_id.end()) {
      result.skipped.push_back(percept.object_id + ": not in GEOMETRY");
      continue;
    }
    // The label the sound suggests; AUDIO carries it, GT is the fallback.
    std::string heard_label = percept.acoustic_label;
    if (heard_label.empty()) {
      const auto object_it = object_by_id.find(percept.object_id);
      if (object_it == object_by_id.end()) {
        result.skipped.push_back(percept.object_id + ": no acoustic label and not in GT_OBJECTS");
        continue;
      }
      heard_label = object_it->second->acoustic_label.empty() ? object_it->second->label
                                                              : object_it->second->acoustic_label;
    }
    const auto& g = *geometry_it->second;
    object_labels_t entry;
    entry.object_id = percept.object_id;
    entry.perceptibility =
        model::acousticPerceptibility(g.distance, percept.occlusion, g.azimuth, parameters);  // eq. 2
    entry.categories = scene.categories;
    entry.confidence = model::labelConfidences(scene.categories, heard_label, entry.perceptibility,  // eq. 3
                                               parameters);
    entry.num_categories = static_cast<int32_t>(entry.categories.size());
    result.labels.objects.push_back(std::move(entry));
  }
  result.labels.num_objects = static_cast<int32_t>(result.labels.objects.size());
  return result;
}

}  // namespace beft::acoustic_labels

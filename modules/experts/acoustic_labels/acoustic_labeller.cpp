#include "experts/acoustic_labels/acoustic_labeller.hpp"

namespace beft::acoustic_labels {

const AcousticLabelling& AcousticLabeller::label(const scene_objects_t& scene, const geometry_percepts_t& geometry,
                                                 const acoustic_percepts_t& audio,
                                                 const model::Parameters& parameters) {
  geometry_by_id_.rebuild(geometry.percepts, &geometry_percept_t::object_id);
  object_by_id_.rebuild(scene.objects, &scene_object_t::id);

  AcousticLabelling& result = result_;
  result.skipped.clear();
  result.labels.utime = audio.utime;
  result.labels.tick = audio.tick;
  result.labels.modality = labels_t::MODALITY_ACOUSTIC;
  std::size_t count = 0;  // entries written: those of earlier ticks are written over
  for (const auto& percept : audio.percepts) {
    const geometry_percept_t* g = geometry_by_id_.find(percept.object_id);
    if (g == nullptr) {
      result.skipped.push_back(percept.object_id + ": not in GEOMETRY");
      continue;
    }
    // The label the sound suggests; AUDIO carries it, GT is the fallback.
    const std::string* heard_label = &percept.acoustic_label;
    if (heard_label->empty()) {
      const scene_object_t* object = object_by_id_.find(percept.object_id);
      if (object == nullptr) {
        result.skipped.push_back(percept.object_id + ": no acoustic label and not in GT_OBJECTS");
        continue;
      }
      heard_label = object->acoustic_label.empty() ? &object->label : &object->acoustic_label;
    }
    if (count == result.labels.objects.size()) result.labels.objects.emplace_back();
    object_labels_t& entry = result.labels.objects[count++];
    entry.object_id = percept.object_id;
    entry.perceptibility = model::acousticPerceptibility(g->distance, percept.occlusion, g->azimuth, parameters);  // eq. 2
    entry.categories = scene.categories;
    model::labelConfidences(scene.categories, *heard_label, entry.perceptibility, parameters,  // eq. 3
                            entry.confidence);
    entry.num_categories = static_cast<int32_t>(entry.categories.size());
  }
  result.labels.objects.resize(count);
  result.labels.num_objects = static_cast<int32_t>(count);
  return result;
}

AcousticLabelling labelAcoustically(const scene_objects_t& scene, const geometry_percepts_t& geometry,
                                    const acoustic_percepts_t& audio, const model::Parameters& parameters) {
  AcousticLabeller labeller;
  return labeller.label(scene, geometry, audio, parameters);
}

}  // namespace beft::acoustic_labels

#include "visual_labels_expert.hpp"

#include "channels.hpp"
#include "log.hpp"
#include "visual_labeller.hpp"

namespace beft::visual_labels {

std::string VisualLabelsExpert::description() const {
  return "Mid-level visual labelling expert: for every object with a visual, v_P = v_d(d_i) * "
         "v_o(O_v) (eq. 1) and the confidence of every category (eq. 3) given its true "
         "category. Reads GT_OBJECTS (categories, labels), GEOMETRY (d_i) and VISION (O_v) of "
         "the fired tick, writes LABELS_VISUAL. To run it alone: feed those three channels "
         "(e.g. lcm-logplayer of a recorded run) and FIRE tokens for 'visual_labels', or use "
         "--replay LOG.";
}

std::vector<expert::ChannelSpec> VisualLabelsExpert::reads() const {
  return {{channels::kGroundTruth, "beft.scene_objects_t"},
          {channels::kGeometry, "beft.geometry_percepts_t"},
          {channels::kVision, "beft.visual_percepts_t"}};
}

std::vector<expert::ChannelSpec> VisualLabelsExpert::writes() const {
  return {{channels::kLabelsVisual, "beft.labels_t"}};
}

std::vector<std::vector<std::string>> VisualLabelsExpert::parameterHelp() const {
  return {{"label_gain", "20", "gain g of eq. 3 (default form)"},
          {"label_form", "default", "eq. 3 form: default (logistic with gain g) or printed (the paper's literal formula)"}};
}

void VisualLabelsExpert::onStartUp(const expert::Parameters& parameters) {
  for (const auto& [key, value] : parameters.all()) model::setParameter(model_, key, value);
}

bool VisualLabelsExpert::onMessage(const std::string& channel, const void* data, int size) {
  if (channel == channels::kGroundTruth) return scene_.store(data, size);
  if (channel == channels::kGeometry) return geometry_.store(data, size);
  if (channel == channels::kVision) return vision_.store(data, size);
  return false;
}

bool VisualLabelsExpert::inputsReady(const expert::Firing& firing) const {
  return scene_.has(firing.tick) && geometry_.has(firing.tick) && vision_.has(firing.tick);
}

expert::Outcome VisualLabelsExpert::fire(const expert::Firing& firing, expert::Output& out) {
  const auto* scene = scene_.ofTick(firing.tick);
  const auto* geometry = geometry_.ofTick(firing.tick);
  const auto* vision = vision_.ofTick(firing.tick);
  if (scene == nullptr || geometry == nullptr || vision == nullptr)
    return expert::Outcome::failure(std::string("no ") +
                                    (scene == nullptr ? "GT_OBJECTS" : geometry == nullptr ? "GEOMETRY" : "VISION") +
                                    " for tick " + std::to_string(firing.tick));
  const VisualLabelling result = labelVisually(*scene, *geometry, *vision, model_);
  for (const auto& reason : result.skipped) log::warn("tick ", firing.tick, ": not labelled: ", reason);
  out.publish(channels::kLabelsVisual, result.labels);
  return expert::Outcome::success();
}

}  // namespace beft::visual_labels

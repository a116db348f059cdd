#include "experts/visual_labels/visual_labels_expert.hpp"

#include "lib/common/channels.hpp"
#include "lib/common/log.hpp"

namespace beft::visual_labels {

std::string VisualLabelsExpert::description() const {
  return "Mid-level visual labelling expert: for every object with a visual, v_P = v_d(d_i) * "
         "v_o(O_v) (eq. 1) and the confidence of every category (eq. 3) given its true "
         "category. Reads GT_OBJECTS (categories, labels), GEOMETRY (d_i) and VISION (O_v) of "
         "the fired tick, writes LABELS_VISUAL. To run it alone: feed those three channels "
         "(e.g. lcm-logplayer of a recorded run) and FIRE tokens for 'visual_labels', or use "
         "--replay LOG.";
}

void VisualLabelsExpert::declareParameters(DeclaredParameters& parameters) {
  model::declareParameters(parameters, model_, {"label_gain", "label_form"});
}

expert::Outcome VisualLabelsExpert::fire(const expert::Firing& firing, expert::Output& out) {
  const auto* scene = scene_.ofTick(firing.tick);
  const auto* geometry = geometry_.ofTick(firing.tick);
  const auto* vision = vision_.ofTick(firing.tick);
  if (scene == nullptr || geometry == nullptr || vision == nullptr)
    return expert::Outcome::failure(std::string("no ") +
                                    (scene == nullptr ? "GT_OBJECTS" : geometry == nullptr ? "GEOMETRY" : "VISION") +
                                    " for tick " + std::to_string(firing.tick));
  const VisualLabelling& result = labeller_.label(*scene, *geometry, *vision, model_);
  for (const auto& reason : result.skipped) log::warn("tick ", firing.tick, ": not labelled: ", reason);
  labels_visual_out_.publish(out, result.labels);
  return expert::Outcome::success();
}

}  // namespace beft::visual_labels

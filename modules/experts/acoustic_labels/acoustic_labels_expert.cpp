#include "experts/acoustic_labels/acoustic_labels_expert.hpp"

#include "lib/common/channels.hpp"
#include "lib/common/log.hpp"

namespace beft::acoustic_labels {

std::string AcousticLabelsExpert::description() const {
  return "Mid-level acoustic labelling expert: for every sounding object, a_P = a_d(d_i) * "
         "a_o(O_a) * a_w(alpha_i) (eq. 2) and the confidence of every category (eq. 3 with a_P) "
         "given the label its sound suggests (its acoustic label). Reads GT_OBJECTS "
         "(categories), GEOMETRY (d_i, alpha_i) and AUDIO (O_a, acoustic label) of the fired "
         "tick, writes LABELS_ACOUSTIC. To run it alone: feed those three channels (e.g. "
         "lcm-logplayer of a recorded run) and FIRE tokens for 'acoustic_labels', or use "
         "--replay LOG.";
}

void AcousticLabelsExpert::declareParameters(DeclaredParameters& parameters) {
  model::declareParameters(parameters, model_, {"aw_variance_deg2", "label_gain", "label_form"});
}

expert::Outcome AcousticLabelsExpert::fire(const expert::Firing& firing, expert::Output& out) {
  const auto* scene = scene_.ofTick(firing.tick);
  const auto* geometry = geometry_.ofTick(firing.tick);
  const auto* audio = audio_.ofTick(firing.tick);
  if (scene == nullptr || geometry == nullptr || audio == nullptr)
    return expert::Outcome::failure(std::string("no ") +
                                    (scene == nullptr ? "GT_OBJECTS" : geometry == nullptr ? "GEOMETRY" : "AUDIO") +
                                    " for tick " + std::to_string(firing.tick));
  const AcousticLabelling& result = labeller_.label(*scene, *geometry, *audio, model_);
  for (const auto& reason : result.skipped) log::warn("tick ", firing.tick, ": not labelled: ", reason);
  labels_acoustic_out_.publish(out, result.labels);
  return expert::Outcome::success();
}

}  // namespace beft::acoustic_labels

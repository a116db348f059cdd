#include "experts/fusion/fusion_expert.hpp"

#include <stdexcept>

#include "lib/common/channels.hpp"
#include "lib/wire/hypothesis_changes.hpp"
#include "lib/common/log.hpp"

namespace beft::fusion {

std::string FusionExpert::description() const {
  return "High-level fusion expert: one hypothesis per object perceived by vision or audition, "
         "kept for the rest of the run. Fused category confidences are the "
         "perceptibility-weighted average of the best visual and the best acoustic evidence so "
         "far (fusion_rule); position from vision when it has seen the object, else the acoustic estimate; "
         "seen (v_P >= seen_threshold), heard, seen_as / heard_as, verified (seen as what it was "
         "heard as) or falsified (seen as something else). Reads GT_OBJECTS, VISION, "
         "LABELS_VISUAL, AUDIO and LABELS_ACOUSTIC of the fired tick (a missing modality is "
         "skipped with a warning), writes HYPOTHESES. When (re)started during a run it resumes from "
         "the last HYPOTHESES on the blackboard. To run it alone: feed those channels (e.g. "
         "lcm-logplayer of a recorded run) and FIRE tokens for 'fusion', or use --replay LOG.";
}

void FusionExpert::declareParameters(DeclaredParameters& parameters) {
  parameters.declare("seen_threshold", config_.seen_threshold, 0, 1,
                     "visual perceptibility v_P from which an object counts as seen (this project's rule; "
                     "g_d(10 m) = 0.5, so at 0.5 nothing beyond 10 m counts as seen)");
  parameters.declareChoice("fusion_rule", config_.rule,
                           {{"weighted_mean", FusionRule::WeightedMean}, {"mean", FusionRule::Mean},
                            {"clearest", FusionRule::Clearest}},
                           "how visual and acoustic label confidences combine (this project's rule): "
                           "perceptibility-weighted mean, plain mean, or the clearer modality's");
  parameters.declare("keyframe_ticks", keyframe_ticks_, 1, 1000000,
                     "HYPOTHESES (the whole list) is published at ticks that are multiples of this (1: every "
                     "tick); HYPOTHESIS_CHANGES every tick carries what changed since");
}

void FusionExpert::onStartUp() { fusion_ = HypothesisFusion(config_); }

expert::Outcome FusionExpert::fire(const expert::Firing& firing, expert::Output& out) {
  const int64_t k = firing.tick;
  TickEvidence evidence;
  evidence.scene = scene_.ofTick(k);
  if (evidence.scene == nullptr) return expert::Outcome::failure("no GT_OBJECTS for tick " + std::to_string(k));
  evidence.vision = vision_.ofTick(k);
  evidence.visual_labels = visual_labels_.ofTick(k);
  evidence.audio = audio_.ofTick(k);
  evidence.acoustic_labels = acoustic_labels_.ofTick(k);
  std::string missing;
  if (evidence.vision == nullptr) missing += " VISION";
  if (evidence.visual_labels == nullptr) missing += " LABELS_VISUAL";
  if (evidence.audio == nullptr) missing += " AUDIO";
  if (evidence.acoustic_labels == nullptr) missing += " LABELS_ACOUSTIC";
  if (!missing.empty()) log::warn("tick ", k, ": fusing without", missing);

  if (last_fused_tick_ < 0) resumeFromBlackboard(k);
  // A tick is folded in once, even if its FIRE is re-run after a lost DONE.
  if (k != last_fused_tick_) {
    fusion_.update(evidence);
    last_fused_tick_ = k;
  }
  fusion_.writeHypotheses(evidence.scene->utime, k, whole_);
  publish(whole_, out);
  return expert::Outcome::success();
}

// After a restart: the hypotheses published earlier in this run, the last
// keyframe with the last changes when they belong to it (a later tick than
// this one means an earlier run, the blackboard outlived it).
void FusionExpert::resumeFromBlackboard(int64_t tick) {
  if (resume_keyframe_ && resume_keyframe_->tick < tick) {
    hypotheses_t whole = *resume_keyframe_;
    if (resume_changes_ && resume_changes_->tick < tick && resume_changes_->tick > whole.tick &&
        !wire::applyChanges(*resume_keyframe_, *resume_changes_, whole))
      log::warn("the last HYPOTHESIS_CHANGES (tick ", resume_changes_->tick, ") do not apply to the last HYPOTHESES (tick ",
                resume_keyframe_->tick, "): resuming from the keyframe");
    fusion_.restore(whole);
    keyframe_ = std::move(*resume_keyframe_);
    log::info("resumed ", fusion_.size(), " hypotheses of tick ", whole.tick, " from the blackboard");
  }
  resume_keyframe_.reset();
  resume_changes_.reset();
}

// The whole list at keyframe ticks (and when none is known yet), the
// changes since the keyframe at every tick.
void FusionExpert::publish(const hypotheses_t& whole, expert::Output& out) {
  const bool keyframe_due = whole.tick % keyframe_ticks_ == 0 || !keyframe_ || keyframe_->tick > whole.tick;
  if (keyframe_due) {
    keyframe_ = whole;
    hypotheses_out_.publish(out, whole);
  }
  changes_out_.publish(out, wire::changesSince(*keyframe_, whole));
}

}  // namespace beft::fusion

// The fusion expert as a process (high level): stores the scene, the
// percepts and the labels of both modalities, and on FIRE for tick k folds
// them into the hypotheses and publishes them: the whole list (HYPOTHESES) at
// keyframes, and every tick what changed since the keyframe
// (HYPOTHESIS_CHANGES; wire/hypothesis_changes.hpp). It also reads both: a
// restarted fusion expert resumes from the hypotheses last published in the
// same run (its own, heard back while it runs, are ignored).
#pragma once

#include <optional>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/hypothesis_changes_t.hpp>
#include <beft/labels_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/visual_percepts_t.hpp>

#include "lib/expert/expert.hpp"
#include "lib/expert/scene_input.hpp"
#include "experts/fusion/hypothesis_fusion.hpp"

namespace beft::fusion {

class FusionExpert : public expert::Expert {
 public:
  std::string name() const override { return "fusion"; }
  std::string description() const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 protected:
  void declareParameters(DeclaredParameters& parameters) override;
  void onStartUp() override;

 private:
  FusionConfig config_;
  HypothesisFusion fusion_;
  int64_t keyframe_ticks_ = 100;
  int64_t last_fused_tick_ = -1;
  std::optional<hypotheses_t> keyframe_;  // the last HYPOTHESES published (or resumed from)
  hypotheses_t whole_{};                  // this tick's whole list, written over the last one's
  // Published before this process started.
  std::optional<hypotheses_t> resume_keyframe_;
  std::optional<hypothesis_changes_t> resume_changes_;

  void resumeFromBlackboard(int64_t tick);
  void publish(const hypotheses_t& whole, expert::Output& out);
  expert::SceneInput scene_{*this};
  expert::TickInput<visual_percepts_t> vision_{*this, channels::kVision};
  expert::TickInput<labels_t> visual_labels_{*this, channels::kLabelsVisual};
  expert::TickInput<acoustic_percepts_t> audio_{*this, channels::kAudio};
  expert::TickInput<labels_t> acoustic_labels_{*this, channels::kLabelsAcoustic};
  // To resume after a restart; its own hypotheses heard back are not decoded.
  expert::HandledInput<hypotheses_t> previous_keyframe_{
      *this, channels::kHypotheses, [this](hypotheses_t&& previous) { resume_keyframe_ = std::move(previous); },
      [this] { return last_fused_tick_ < 0; }};
  expert::HandledInput<hypothesis_changes_t> previous_changes_{
      *this, channels::kHypothesisChanges,
      [this](hypothesis_changes_t&& previous) { resume_changes_ = std::move(previous); },
      [this] { return last_fused_tick_ < 0; }};
  expert::OutputPort<hypotheses_t> hypotheses_out_{*this, channels::kHypotheses};
  expert::OutputPort<hypothesis_changes_t> changes_out_{*this, channels::kHypothesisChanges};
};

}  // namespace beft::fusion

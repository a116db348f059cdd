// The fusion expert as a process (high level): stores the scene, the
// percepts and the labels of both modalities, and on FIRE for tick k folds
// them into the hypotheses and publishes HYPOTHESES. It also reads
// HYPOTHESES: a restarted fusion expert resumes from the hypotheses last
// published in the same run (its own, heard back while it runs, are ignored).
#pragma once

#include <optional>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/labels_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/visual_percepts_t.hpp>

#include "expert.hpp"
#include "hypothesis_fusion.hpp"
#include "tick_channel.hpp"

namespace beft::fusion {

class FusionExpert : public expert::Expert {
 public:
  std::string name() const override { return "fusion"; }
  std::string description() const override;
  std::vector<expert::ChannelSpec> reads() const override;
  std::vector<expert::ChannelSpec> writes() const override;
  std::vector<std::vector<std::string>> parameterHelp() const override;
  void onStartUp(const expert::Parameters& parameters) override;
  bool onMessage(const std::string& channel, const void* data, int size) override;
  bool inputsReady(const expert::Firing& firing) const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 private:
  HypothesisFusion fusion_;
  int64_t last_fused_tick_ = -1;
  std::optional<hypotheses_t> resume_;  // published before this process started
  expert::TickChannel<scene_objects_t> scene_;
  expert::TickChannel<visual_percepts_t> vision_;
  expert::TickChannel<labels_t> visual_labels_;
  expert::TickChannel<acoustic_percepts_t> audio_;
  expert::TickChannel<labels_t> acoustic_labels_;
};

}  // namespace beft::fusion

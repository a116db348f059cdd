// The acoustic labelling expert as a process (mid level): stores GT_OBJECTS,
// GEOMETRY and AUDIO, and on FIRE for tick k publishes LABELS_ACOUSTIC.
#pragma once

#include <beft/acoustic_percepts_t.hpp>
#include <beft/geometry_percepts_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "expert.hpp"
#include "model.hpp"
#include "tick_channel.hpp"

namespace beft::acoustic_labels {

class AcousticLabelsExpert : public expert::Expert {
 public:
  std::string name() const override { return "acoustic_labels"; }
  std::string description() const override;
  std::vector<expert::ChannelSpec> reads() const override;
  std::vector<expert::ChannelSpec> writes() const override;
  std::vector<std::vector<std::string>> parameterHelp() const override;
  void onStartUp(const expert::Parameters& parameters) override;
  bool onMessage(const std::string& channel, const void* data, int size) override;
  bool inputsReady(const expert::Firing& firing) const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 private:
  model::Parameters model_;
  expert::TickChannel<scene_objects_t> scene_;
  expert::TickChannel<geometry_percepts_t> geometry_;
  expert::TickChannel<acoustic_percepts_t> audio_;
};

}  // namespace beft::acoustic_labels

// The acoustic labelling expert as a process (mid level): stores GT_OBJECTS,
// GEOMETRY and AUDIO, and on FIRE for tick k publishes LABELS_ACOUSTIC.
#pragma once

#include <beft/acoustic_percepts_t.hpp>
#include <beft/geometry_percepts_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "experts/acoustic_labels/acoustic_labeller.hpp"
#include "lib/expert/expert.hpp"
#include "lib/expert/scene_input.hpp"
#include "lib/model/model.hpp"

namespace beft::acoustic_labels {

class AcousticLabelsExpert : public expert::Expert {
 public:
  std::string name() const override { return "acoustic_labels"; }
  std::string description() const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 protected:
  void declareParameters(DeclaredParameters& parameters) override;

 private:
  model::Parameters model_;
  AcousticLabeller labeller_;
  expert::SceneInput scene_{*this};
  expert::TickInput<geometry_percepts_t> geometry_{*this, channels::kGeometry};
  expert::TickInput<acoustic_percepts_t> audio_{*this, channels::kAudio};
  expert::OutputPort<labels_t> labels_acoustic_out_{*this, channels::kLabelsAcoustic};
};

}  // namespace beft::acoustic_labels

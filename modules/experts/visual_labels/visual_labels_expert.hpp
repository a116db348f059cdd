// The visual labelling expert as a process (mid level): stores GT_OBJECTS,
// GEOMETRY and VISION, and on FIRE for tick k publishes LABELS_VISUAL.
#pragma once

#include <beft/geometry_percepts_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/visual_percepts_t.hpp>

#include "lib/expert/expert.hpp"
#include "experts/visual_labels/visual_labeller.hpp"
#include "lib/expert/scene_input.hpp"
#include "lib/model/model.hpp"

namespace beft::visual_labels {

class VisualLabelsExpert : public expert::Expert {
 public:
  std::string name() const override { return "visual_labels"; }
  std::string description() const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 protected:
  void declareParameters(DeclaredParameters& parameters) override;

 private:
  model::Parameters model_;
  VisualLabeller labeller_;
  expert::SceneInput scene_{*this};
  expert::TickInput<geometry_percepts_t> geometry_{*this, channels::kGeometry};
  expert::TickInput<visual_percepts_t> vision_{*this, channels::kVision};
  expert::OutputPort<labels_t> labels_visual_out_{*this, channels::kLabelsVisual};
};

}  // namespace beft::visual_labels

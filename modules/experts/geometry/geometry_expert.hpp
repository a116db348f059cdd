// The geometry expert as a process (low level): stores GT_OBJECTS and
// ROBOT_STATE, and on FIRE for tick k publishes GEOMETRY for tick k.
#pragma once

#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "lib/expert/expert.hpp"
#include "lib/expert/scene_input.hpp"

namespace beft::geometry {

class GeometryExpert : public expert::Expert {
 public:
  std::string name() const override { return "geometry"; }
  std::string description() const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 protected:
  void declareParameters(DeclaredParameters& parameters) override;

 private:
  bool every_object_ = false;
  expert::SceneInput scene_{*this};
  expert::TickInput<robot_state_t> robot_{*this, channels::kRobotState};
  expert::OutputPort<geometry_percepts_t> geometry_out_{*this, channels::kGeometry};
};

}  // namespace beft::geometry

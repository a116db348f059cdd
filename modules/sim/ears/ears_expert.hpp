// beft-ears as a process: stores GT_OBJECTS and ROBOT_STATE, and on FIRE for
// tick k publishes on EARS what the two ears heard from tick k-1 to tick k.
#pragma once

#include <memory>
#include <optional>

#include <beft/binaural_block_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "lib/hearing/binaural_renderer.hpp"
#include "sim/ears/ear_signals.hpp"
#include "lib/expert/expert.hpp"
#include "lib/expert/scene_input.hpp"
#include "lib/hearing/sound_bank.hpp"

namespace beft::ears {

class EarsExpert : public expert::Expert {
 public:
  std::string name() const override { return "ears"; }
  std::string description() const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 protected:
  void declareParameters(DeclaredParameters& parameters) override;
  void onStartUp() override;

 private:
  EarsConfig config_;
  std::string scenario_;   // the scene objects' sounds are relative to its folder
  std::string hrirs_;      // "" = the KEMAR set (spherical head if missing), "spherical" = the model
  std::optional<hearing::BinauralRenderer> renderer_;
  std::optional<EarsRoom> room_;  // the scenario's <acoustics>; none: the free field
  std::unique_ptr<hearing::SoundBank> sounds_;
  expert::SceneInput scene_{*this};
  expert::TickInput<robot_state_t> robot_{*this, channels::kRobotState};
  expert::OutputPort<binaural_block_t> ears_out_{*this, channels::kEars};
};

}  // namespace beft::ears

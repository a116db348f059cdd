// The audio expert as a process (low level): stores GT_OBJECTS and
// ROBOT_STATE, and on FIRE for tick k publishes AUDIO for tick k.
#pragma once

#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "audio_estimator.hpp"
#include "expert.hpp"

namespace beft::audio {

class AudioExpert : public expert::Expert {
 public:
  std::string name() const override { return "audio"; }
  std::string description() const override;
  bool inputsReady(const expert::Firing& firing) const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 protected:
  void declareParameters(DeclaredParameters& parameters) override;
  void onStartUp() override;

 private:
  AudioConfig config_;
  int64_t seed_ = 0;  // of the position noise
  expert::TickInput<scene_objects_t> scene_{*this, channels::kGroundTruth};
  expert::TickInput<robot_state_t> robot_{*this, channels::kRobotState};
  expert::OutputPort<acoustic_percepts_t> audio_out_{*this, channels::kAudio};
};

}  // namespace beft::audio

// The audio expert as a process (low level): stores GT_OBJECTS and
// ROBOT_STATE, and on FIRE for tick k publishes AUDIO for tick k.
#pragma once

#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "audio_estimator.hpp"
#include "expert.hpp"
#include "tick_channel.hpp"

namespace beft::audio {

class AudioExpert : public expert::Expert {
 public:
  std::string name() const override { return "audio"; }
  std::string description() const override;
  std::vector<expert::ChannelSpec> reads() const override;
  std::vector<expert::ChannelSpec> writes() const override;
  std::vector<std::vector<std::string>> parameterHelp() const override;
  void onStartUp(const expert::Parameters& parameters) override;
  bool onMessage(const std::string& channel, const void* data, int size) override;
  bool inputsReady(const expert::Firing& firing) const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 private:
  AudioConfig config_;
  expert::TickChannel<scene_objects_t> scene_;
  expert::TickChannel<robot_state_t> robot_;
};

}  // namespace beft::audio

// The audio expert as a process (low level): stores GT_OBJECTS and
// ROBOT_STATE (and, with acoustics=binaural, EARS and the HYPOTHESES of the
// tick before), and on FIRE for tick k
// publishes AUDIO for tick k (and, hearing, a head turn on TASK_COMMAND when
// front and back cannot be told apart).
#pragma once

#include <map>
#include <memory>
#include <optional>

#include <beft/binaural_block_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/task_command_t.hpp>

#include "experts/audio/audio_estimator.hpp"
#include "lib/hearing/band_signature.hpp"
#include "lib/hearing/block_localiser.hpp"
#include "lib/expert/expert.hpp"
#include "lib/expert/hypotheses_input.hpp"
#include "lib/expert/scene_input.hpp"
#include "experts/audio/heard_sources.hpp"
#include "lib/expert/helper_task.hpp"
#include "lib/scene/scene_solids.hpp"
#include "lib/hearing/sound_bank.hpp"

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
  enum class Acoustics { GroundTruth, Binaural };
  // Which of the localiser's profiles hears (binaural): the defaults, the
  // reverberant one (hearing::LocaliserConfig::reverberant), or whichever
  // the place calls for (the scenario's <acoustics>: reverberant).
  enum class Profile { Place, FreeField, Reverberant };
  expert::Outcome fireHearing(const expert::Firing& firing, const scene_objects_t& scene,
                              const robot_state_t& robot, expert::Output& out);
  const hearing::BandSignature* signatureOf(const std::string& sound);
  std::vector<SoundingObject> soundingObjects(const expert::Firing& firing, const scene_objects_t& scene);
  void askForHeadTurn(const expert::Firing& firing, const robot_state_t& robot, expert::Output& out);

  AudioConfig config_;
  int64_t seed_ = 0;  // of the position noise
  Acoustics acoustics_ = Acoustics::GroundTruth;
  std::string scenario_;  // the sounds' folder (binaural)
  Profile profile_ = Profile::Place;
  HearingConfig hearing_config_;
  double head_yaw_limit_deg_ = 80;
  int64_t turn_priority_ = 90;
  std::optional<hearing::BlockLocaliser> localiser_;
  std::unique_ptr<hearing::SoundBank> sounds_;
  std::map<std::string, std::optional<hearing::BandSignature>> signatures_;  // by sound file
  std::optional<HeardSources> heard_;
  int64_t next_command_id_ = 1;
  bool warned_about_rate_ = false;
  expert::SceneInput scene_{*this};
  expert::TickInput<robot_state_t> robot_{*this, channels::kRobotState};
  expert::TickInput<binaural_block_t> ears_{*this, channels::kEars, 16, admitBlock, /*optional_until_heard=*/true};
  // Binaural: where vision placed the objects, as the fusion (which fires
  // after this expert in a tick) said at the tick before.
  expert::HypothesesInput placed_{*this};
  expert::OutputPort<acoustic_percepts_t> audio_out_{*this, channels::kAudio};
  expert::OutputPort<task_command_t> task_command_out_{*this, channels::kTaskCommand};
  camera::SceneSolids solids_;      // of the scene last fired
  expert::HelperTask occluding_;    // last: its thread ends before the state it works on goes

  static bool admitBlock(binaural_block_t& block, std::string* why);
};

}  // namespace beft::audio

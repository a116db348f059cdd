#include "audio_expert.hpp"

#include <stdexcept>

#include "channels.hpp"

namespace beft::audio {

std::string AudioExpert::description() const {
  return "Low-level audio expert: for every object that sounds now, the acoustic occlusion O_a "
         "(share of the lines from 9 sample points of the source - one for a source without a "
         "visual - to the two ears, +-0.09 m beside the head at camera height, that pass through "
         "another object), the position estimate p_hat (true position; with "
         "--param position_noise=1 plus seeded Gaussian noise of spread noise_max_m * (1 - a_P)), "
         "the label its sound suggests, its activity and level. Reads GT_OBJECTS and ROBOT_STATE "
         "of the fired tick, writes AUDIO. To run it alone: start beft-world and feed FIRE "
         "tokens for 'audio' (or run the arbiter), and watch AUDIO with lcm-spy.";
}

std::vector<expert::ChannelSpec> AudioExpert::reads() const {
  return {{channels::kGroundTruth, "beft.scene_objects_t"}, {channels::kRobotState, "beft.robot_state_t"}};
}

std::vector<expert::ChannelSpec> AudioExpert::writes() const {
  return {{channels::kAudio, "beft.acoustic_percepts_t"}};
}

std::vector<std::vector<std::string>> AudioExpert::parameterHelp() const {
  return {{"position_noise", "0", "1: add seeded noise to p_hat, spread growing as a_P falls"},
          {"noise_max_m", "2.0", "noise spread (standard deviation per axis) at a_P = 0 [m]"},
          {"seed", "0", "seed of the position noise (use the scenario's seed)"},
          {"aw_variance_deg2", "8100", "variance s of a_w(alpha) in eq. 2, for the noise's a_P [deg^2]"}};
}

void AudioExpert::onStartUp(const expert::Parameters& parameters) {
  config_.noise.enabled = parameters.getBool("position_noise", false);
  config_.noise.max_sigma = parameters.getDouble("noise_max_m", config_.noise.max_sigma);
  if (!(config_.noise.max_sigma >= 0)) throw std::invalid_argument("noise_max_m must be >= 0");
  const int64_t seed = parameters.getInt("seed", 0);
  config_.noise.seed = static_cast<uint64_t>(seed);
  if (parameters.has("aw_variance_deg2"))
    model::setParameter(config_.model, "aw_variance_deg2", parameters.getString("aw_variance_deg2", ""));
}

bool AudioExpert::onMessage(const std::string& channel, const void* data, int size) {
  if (channel == channels::kGroundTruth) return scene_.store(data, size);
  if (channel == channels::kRobotState) return robot_.store(data, size);
  return false;
}

bool AudioExpert::inputsReady(const expert::Firing& firing) const {
  return scene_.has(firing.tick) && robot_.has(firing.tick);
}

expert::Outcome AudioExpert::fire(const expert::Firing& firing, expert::Output& out) {
  const auto* scene = scene_.ofTick(firing.tick);
  const auto* robot = robot_.ofTick(firing.tick);
  if (scene == nullptr || robot == nullptr)
    return expert::Outcome::failure(std::string("no ") + (scene == nullptr ? "GT_OBJECTS" : "ROBOT_STATE") +
                                    " for tick " + std::to_string(firing.tick));
  const camera::SceneGeometry solids = camera::SceneGeometry::fromMessage(*scene);
  out.publish(channels::kAudio, estimateAudio(*scene, solids, *robot, config_));
  return expert::Outcome::success();
}

}  // namespace beft::audio

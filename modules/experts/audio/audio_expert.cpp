#include "audio_expert.hpp"

#include <limits>

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

void AudioExpert::declareParameters(DeclaredParameters& parameters) {
  parameters.declare("position_noise", config_.noise.enabled, "1: add seeded noise to p_hat, spread growing as a_P falls");
  parameters.declare("noise_max_m", config_.noise.max_sigma, 0, DeclaredParameters::kNoLimit,
                     "noise spread (standard deviation per axis) at a_P = 0 [m]");
  parameters.declare("seed", seed_, 0, std::numeric_limits<int64_t>::max(),
                     "seed of the position noise (use the scenario's seed)");
  model::declareParameters(parameters, config_.model, {"aw_variance_deg2"});
}

void AudioExpert::onStartUp() {
  config_.noise.seed = static_cast<uint64_t>(seed_);
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
  audio_out_.publish(out, estimateAudio(*scene, solids, *robot, config_));
  return expert::Outcome::success();
}

}  // namespace beft::audio

#include "sim/ears/ears_expert.hpp"

#include <filesystem>
#include <limits>

#include "lib/common/channels.hpp"
#include "lib/common/log.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/scene/scene_geometry.hpp"

namespace beft::ears {

std::string EarsExpert::description() const {
  return "The robot's two ears: every sounding object's sound (its WAV, looped from the run's start, resampled "
         "to the impulse responses' rate) rendered for the head's pose with head-related impulse responses (the "
         "KEMAR set of the SoundScape Renderer; a spherical-head model if it is missing), 1/r gain and "
         "propagation delay, occluded sources muffled by O_a, a turning head cross-faded, seeded sensor noise; "
         "with the scenario's <acoustics>, early reflections off the scene's solids and the ground (image sources) "
         "and a diffuse tail of its T60. "
         "Reads GT_OBJECTS and ROBOT_STATE of the fired tick (and ROBOT_STATE of the tick before), writes EARS: "
         "the samples from the previous tick's time to this one's. Started by ./beft run --acoustics binaural; "
         "./beft listen LOG --out ears.wav writes what it heard.";
}

void EarsExpert::declareParameters(DeclaredParameters& parameters) {
  parameters.declare("scenario", scenario_, "scenario file; the objects' sounds are relative to its folder");
  parameters.declare("hrirs", hrirs_, "impulse responses: empty = KEMAR (SoundScape Renderer's), 'spherical' = model, or a WAV of the same layout");
  parameters.declare("seed", config_.seed, 0, std::numeric_limits<int64_t>::max(), "seed of the sensor noise");
  parameters.declare("noise_rms", config_.noise_rms, 0, 1, "sensor noise level (1 = a level-1 source at 1 m) [-]");
  parameters.declare("max_sources", config_.max_sources, 1, 64, "render only this many of the loudest sources");
}

void EarsExpert::onStartUp() {
  auto warn = [](const std::string& text) { log::warn(text); };
  hearing::HrirSet hrirs = hrirs_.empty()           ? hearing::HrirSet::loadDefault(warn)
                           : hrirs_ == "spherical" ? hearing::HrirSet::sphericalHead()
                                                   : hearing::HrirSet::loadKemar(hrirs_);
  log::info("ears: ", hrirs.name(), ", ", hrirs.directionCount(), " directions, ", hrirs.length(), " taps at ",
            hrirs.sampleRate(), " Hz");
  const double rate = hrirs.sampleRate();
  renderer_.emplace(std::move(hrirs), rate);
  const std::string folder =
      scenario_.empty() ? std::string(".") : std::filesystem::path(scenario_).parent_path().string();
  if (scenario_.empty()) log::warn("ears: no --param scenario=FILE: sounds are looked up from the current folder");
  sounds_ = std::make_unique<hearing::SoundBank>(folder.empty() ? "." : folder, rate, warn);
  if (!scenario_.empty()) {
    room_ = roomOfScenario(scenario::loadScenario(scenario_, nullptr), renderer_->hrirs(), rate);
    if (room_)
      log::info("ears: room acoustics, reflection order ", room_->base.settings().reflection_order, ", T60 ",
                room_->base.settings().t60_s, " s, ground ", room_->base.settings().ground ? "reflecting" : "silent");
  }
}

expert::Outcome EarsExpert::fire(const expert::Firing& firing, expert::Output& out) {
  const auto* scene = scene_.ofTick(firing.tick);
  const auto* robot = robot_.ofTick(firing.tick);
  if (scene == nullptr || robot == nullptr)
    return expert::Outcome::failure(std::string("no ") + (scene == nullptr ? "GT_OBJECTS" : "ROBOT_STATE") +
                                    " for tick " + std::to_string(firing.tick));
  const robot_state_t* previous = firing.tick > 0 ? robot_.ofTick(firing.tick - 1) : nullptr;
  const camera::SceneGeometry solids = camera::SceneGeometry::fromMessage(*scene);
  const double rate = renderer_->sampleRate();
  hearing::BlockRequest request = blockRequest(*scene, solids, *robot, previous, *sounds_, rate, config_);
  std::optional<hearing::RoomModel> room;
  if (room_) {
    room.emplace(roomOfTick(*room_, *scene, solids));
    request.room = &*room;
  }
  ears_out_.publish(out, blockMessage(renderer_->render(request), request, *robot, rate));
  return expert::Outcome::success();
}

}  // namespace beft::ears

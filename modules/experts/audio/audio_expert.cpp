#include "experts/audio/audio_expert.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "lib/common/channels.hpp"
#include "experts/audio/heard_percepts.hpp"
#include "lib/common/log.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/scene/object_geometry.hpp"
#include "lib/task/task_commands.hpp"

namespace beft::audio {

std::string AudioExpert::description() const {
  return "Low-level audio expert: for every object that sounds now, the acoustic occlusion O_a "
         "(share of the lines from 9 sample points of the source - one for a source without a "
         "visual - to the two ears, +-0.09 m beside the head at camera height, that pass through "
         "another object), the position estimate p_hat (true position; with "
         "--param position_noise=1 plus seeded Gaussian noise of spread noise_max_m * (1 - a_P)), "
         "the label its sound suggests, its activity and level. Reads GT_OBJECTS and ROBOT_STATE "
         "of the fired tick, writes AUDIO. With --param acoustics=binaural (./beft run --acoustics binaural) "
         "p_hat comes from what the ears heard (EARS): each block localised against interaural templates of "
         "the MIT KEMAR head (libmysofa), its peaks matched to the sounding objects by spectrum (among objects of one "
         "sound, a peak from where vision placed one, by HYPOTHESES of the tick before, is that one's), a world-frame "
         "direction per object kept over the blocks (a turning head resolves front and back; when it stays "
         "ambiguous a turn_head task is pushed on TASK_COMMAND), the distance triangulated over the robot's "
         "own motion; O_a is computed for a source at p_hat. To run it alone: start beft-world and feed FIRE "
         "tokens for 'audio' (or run the arbiter), and watch AUDIO with lcm-spy.";
}

void AudioExpert::declareParameters(DeclaredParameters& parameters) {
  parameters.declare("position_noise", config_.noise.enabled, "1: add seeded noise to p_hat, spread growing as a_P falls");
  parameters.declare("noise_max_m", config_.noise.max_sigma, 0, DeclaredParameters::kNoLimit,
                     "noise spread (standard deviation per axis) at a_P = 0 [m]");
  parameters.declare("seed", seed_, 0, std::numeric_limits<int64_t>::max(),
                     "seed of the position noise (use the scenario's seed)");
  model::declareParameters(parameters, config_.model, {"aw_variance_deg2"});
  parameters.declareChoice("acoustics", acoustics_,
                           {{"ground_truth", Acoustics::GroundTruth}, {"binaural", Acoustics::Binaural}},
                           "p_hat from ground truth (the paper's experiments) or from the ear signals on EARS");
  parameters.declare("scenario", scenario_, "scenario file; binaural: the objects' sounds are relative to its folder");
  parameters.declareChoice("localiser", profile_,
                           {{"place", Profile::Place}, {"free_field", Profile::FreeField},
                            {"reverberant", Profile::Reverberant}},
                           "binaural: the localiser's profile: free_field (its defaults), reverberant (onset "
                           "weighting, interaural-coherence selection, every bin alike), or place: reverberant "
                           "when the scenario has <acoustics>");
  parameters.declare("default_distance_m", hearing_config_.default_distance_m, 0.5, 50,
                     "binaural: distance of an estimate before the bearings cross [m]");
  parameters.declare("fix_agreement_deg", hearing_config_.fix_agreement_deg, 0, 90,
                     "binaural: where the bearings last crossed is kept as the estimate while the heard direction "
                     "points this near it, after the lines have aged out (0: not kept) [deg]");
  parameters.declare("fix_disagreement_s", hearing_config_.fix_disagreement_s, 0, 60,
                     "binaural: the kept crossing is dropped once the clear heard direction has missed it by more "
                     "than fix_agreement_deg for this long [s]");
  parameters.declare("fix_aging_mps", hearing_config_.fix_aging_mps, 0, 10,
                     "binaural: a new crossing of the bearings replaces the kept one only if its error is no larger "
                     "than the kept one's grown by this per second since it was made (0: the better crossing stays "
                     "while it is heard there) [m/s]");
  parameters.declare("seen_explains_deg", hearing_config_.seen_explains_deg, 0, 45,
                     "binaural: among objects of one sound, a peak this near the direction of one that vision has "
                     "placed (HYPOTHESES of the tick before), or of its mirror image, is that one's, and any seen "
                     "object takes only those (0: spectra and tracks only) [deg]");
  parameters.declare("turn_deg", hearing_config_.turn_deg, 5, 60,
                     "binaural: head turn asked for when front and back cannot be told apart [deg]");
  parameters.declare("turn_priority", turn_priority_, 0, 1000, "binaural: priority of that turn_head task");
  parameters.declare("head_yaw_limit_deg", head_yaw_limit_deg_, 0, 180,
                     "binaural: the head turns no farther than this either way [deg]");
}

void AudioExpert::onStartUp() {
  config_.noise.seed = static_cast<uint64_t>(seed_);
  placed_.readTheTickBefore();
  // Only hearing uses the ears and the hypotheses: without it they are not
  // even subscribed to (hundreds of hypotheses a tick, decoded for nothing).
  ears_.setRead(acoustics_ == Acoustics::Binaural);
  placed_.setRead(acoustics_ == Acoustics::Binaural);
  if (acoustics_ != Acoustics::Binaural) return;
  auto templates = hearing::InterauralTemplates::fromSofa();
  const double rate = templates.layout().sample_rate;
  bool reverberant = profile_ == Profile::Reverberant;
  if (profile_ == Profile::Place && !scenario_.empty()) {
    try {
      reverberant = scenario::loadScenario(scenario_, nullptr).acoustics.has_value();
    } catch (const std::exception& e) {
      log::warn("audio: cannot read ", scenario_, " for its <acoustics> (", e.what(), "): the free-field localiser");
    }
  }
  localiser_.emplace(std::move(templates),
                     reverberant ? hearing::LocaliserConfig::reverberant() : hearing::LocaliserConfig{});
  const std::string folder = std::filesystem::path(scenario_).parent_path().string();
  if (scenario_.empty()) log::warn("audio: no --param scenario=FILE: sounds are looked up from the current folder");
  sounds_ = std::make_unique<hearing::SoundBank>(folder.empty() ? "." : folder, rate,
                                                 [](const std::string& text) { log::warn(text); });
  heard_.emplace(hearing_config_);
  log::info("audio: localising the ear signals (templates of the MIT KEMAR head, ",
            reverberant ? "reverberant" : "free-field", " profile)");
}

bool AudioExpert::admitBlock(binaural_block_t& block, std::string* why) {
  constexpr int kMaxSamples = 10 * 48000;  // 10 s of one ear: far beyond any tick
  if (!(block.full_scale > 0) || !std::isfinite(block.full_scale)) {
    *why = "full_scale is not a positive number";
    return false;
  }
  if (block.num_samples > kMaxSamples) {
    *why = "more than 10 s of samples in one block";
    return false;
  }
  return true;
}

bool AudioExpert::inputsReady(const expert::Firing& firing) const {
  const bool heard = acoustics_ != Acoustics::Binaural || ears_.has(firing.tick);
  // The hypotheses of the tick before, while the fusion publishes them (a
  // net without it, or the first ticks, go without).
  const hypotheses_t* placed = acoustics_ == Acoustics::Binaural ? placed_.latest() : nullptr;
  const bool placed_missing = placed != nullptr && placed->tick >= firing.tick - 2 && placed->tick < firing.tick - 1;
  return scene_.has(firing.tick) && robot_.has(firing.tick) && heard && !placed_missing;
}

const hearing::BandSignature* AudioExpert::signatureOf(const std::string& sound) {
  auto found = signatures_.find(sound);
  if (found == signatures_.end()) {
    std::optional<hearing::BandSignature> signature;
    if (const hearing::SourceSignal* signal = sounds_->sound(sound)) {
      const auto& layout = localiser_->templates().layout();
      signature = hearing::signatureOfSound(signal->samples, layout.sample_rate, layout);
    }
    found = signatures_.emplace(sound, std::move(signature)).first;
  }
  return found->second ? &*found->second : nullptr;
}

// The objects that sound now, each with where vision placed it (the fusion's
// position of a hypothesis that was seen) at the tick before.
std::vector<SoundingObject> AudioExpert::soundingObjects(const expert::Firing& firing, const scene_objects_t& scene) {
  std::unordered_map<std::string, Eigen::Vector2d> seen_at;
  if (const hypotheses_t* placed = placed_.ofTick(firing.tick - 1))
    for (const auto& h : placed->hypotheses)
      if (h.seen && std::isfinite(h.x) && std::isfinite(h.y)) seen_at.emplace(h.object_id, Eigen::Vector2d(h.x, h.y));
  std::vector<SoundingObject> sounding;
  for (const auto& object : scene.objects) {
    if (!geometry::isSounding(object)) continue;
    SoundingObject heard{object.id, signatureOf(object.sound), std::nullopt};
    if (const auto found = seen_at.find(object.id); found != seen_at.end()) heard.seen_at = found->second;
    sounding.push_back(std::move(heard));
  }
  return sounding;
}

void AudioExpert::askForHeadTurn(const expert::Firing& firing, const robot_state_t& robot, expert::Output& out) {
  std::string object_id;
  const auto target = heard_->wantsHeadTurn(robot.head_yaw, head_yaw_limit_deg_, firing.utime, &object_id);
  if (!target) return;
  tasks::Task turn;
  turn.kind = tasks::kinds::kTurnHead;
  turn.priority = static_cast<int>(turn_priority_);
  turn.yaw = *target;
  turn.object_id = object_id;
  turn.origin = "audio";
  turn.note = "front or back? " + object_id + " is heard where its mirror image would be heard too";
  task_command_out_.publish(out, tasks::pushCommand(turn, firing.utime, next_command_id_++));
}

expert::Outcome AudioExpert::fireHearing(const expert::Firing& firing, const scene_objects_t& scene,
                                         const robot_state_t& robot, expert::Output& out) {
  const auto* block = ears_.ofTick(firing.tick);
  if (block == nullptr) return expert::Outcome::failure("no EARS for tick " + std::to_string(firing.tick));
  const std::size_t count = std::min(block->left.size(), block->right.size());
  std::vector<float> left(count), right(count);
  const double scale = block->full_scale / 32767.0;
  for (std::size_t i = 0; i < count; ++i) {
    left[i] = static_cast<float>(block->left[i] * scale);
    right[i] = static_cast<float>(block->right[i] * scale);
  }
  const double rate = localiser_->templates().layout().sample_rate;
  if (block->sample_rate != static_cast<int32_t>(std::lround(rate))) {
    // Another renderer's blocks: not heard (said once), the estimates stay as they were.
    if (!warned_about_rate_)
      log::warn("audio: EARS blocks at ", block->sample_rate, " Hz, the templates are for ", rate, " Hz: not heard");
    warned_about_rate_ = true;
    left.clear();
    right.clear();
  }
  heard_->hear(localiser_->localise(left, right), *block, soundingObjects(firing, scene));
  solids_.update(scene);
  audio_out_.publish(out, heardPercepts(scene, solids_.solids(), robot, *heard_));
  askForHeadTurn(firing, robot, out);
  return expert::Outcome::success();
}

expert::Outcome AudioExpert::fire(const expert::Firing& firing, expert::Output& out) {
  const auto* scene = scene_.ofTick(firing.tick);
  const auto* robot = robot_.ofTick(firing.tick);
  if (scene == nullptr || robot == nullptr)
    return expert::Outcome::failure(std::string("no ") + (scene == nullptr ? "GT_OBJECTS" : "ROBOT_STATE") +
                                    " for tick " + std::to_string(firing.tick));
  if (acoustics_ == Acoustics::Binaural) return fireHearing(firing, *scene, *robot, out);
  // The solids are made again only when the objects change; the occlusions
  // are shared with a helper thread (estimateAudio).
  solids_.update(*scene);
  audio_out_.publish(out, estimateAudio(*scene, solids_.solids(), *robot, config_, &occluding_));
  return expert::Outcome::success();
}

}  // namespace beft::audio

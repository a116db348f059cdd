// What the two ears hear during one tick: the request to the binaural
// renderer built from the tick's scene and head pose (and the previous
// tick's, which the block cross-fades from), and the block as a message.
// Stateless: a tick's block follows from the two ticks' messages alone, so a
// restarted process renders the same samples.
#pragma once

#include <beft/binaural_block_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

#include <map>
#include <optional>
#include <string>

#include "lib/hearing/binaural_renderer.hpp"
#include "lib/hearing/room_model.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/scene/scene_geometry.hpp"
#include "lib/hearing/sound_bank.hpp"

namespace beft::ears {

struct EarsConfig {
  int64_t seed = 0;            // of the sensor noise
  double noise_rms = 1e-4;     // sensor noise, in units of a source of level 1 heard at 1 m [-]
  int max_sources = 8;         // render only the loudest sources at the ears (1/r * level) [-]
  double first_block_s = 0.1;  // length of a block with no previous tick to start from [s]
};

// The samples of tick `robot.tick`: from the previous tick's time (or
// first_block_s before, not before 0) to this tick's. previous: the robot
// state of the tick before, or null.
hearing::BlockRequest blockRequest(const scene_objects_t& scene, const camera::SceneGeometry& solids,
                                   const robot_state_t& robot, const robot_state_t* previous,
                                   hearing::SoundBank& sounds, double sample_rate, const EarsConfig& config);

// The room a scenario's <acoustics> makes for the ears (none without the
// element: the free field, rendered exactly as before rooms existed).
struct EarsRoom {
  hearing::RoomModel base;                   // the settings and the tail; no boxes yet
  std::map<std::string, double> absorption;  // object id -> share of energy its faces absorb
  double default_absorption = 0.2;           // <acoustics absorption>
};
// Settings from <acoustics>: order, ground (absorbing the scenario's
// absorption), T60, the scenario's seed; the volume for the tail's energy
// balance is the world's area times the tallest solid (at least 2.5 m).
std::optional<EarsRoom> roomOfScenario(const scenario::Scenario& scenario, const hearing::HrirSet& hrirs,
                                       double sample_rate);
// The tick's room: every solid of the scene a reflecting box (a cylinder by
// its bounding box), owned by its object index, with its object's absorption.
hearing::RoomModel roomOfTick(const EarsRoom& room, const scene_objects_t& scene, const camera::SceneGeometry& solids);

// The rendered samples as 16-bit values scaled to the block's peak.
binaural_block_t blockMessage(const hearing::StereoBlock& block, const hearing::BlockRequest& request,
                              const robot_state_t& robot, double sample_rate);

}  // namespace beft::ears

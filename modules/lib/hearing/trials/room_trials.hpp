// Trials of the localiser in rooms, after the protocol of Ma, May and Brown
// (2017, IEEE/ACM TASLP 25(12), "Exploiting deep neural networks and head
// movements for robust binaural localization of multiple sources in
// reverberant environments"): 1 to 3 simultaneous talkers at azimuths
// drawn over the full 360 degrees, 1.5 m from the head, in rooms of
// increasing T60; a source counts as localised when a peak lies within
// 5 degrees of it, the number of talkers known (the strongest N peaks).
// The rooms are not the Surrey rooms (their BRIRs cover the frontal half
// only and are not shipped here) but shoeboxes of 16 x 12 x 4 m whose
// absorption gives Eyring's T60 the T60 asked for, rendered by
// BinauralRenderer with image sources up to order 2 and the diffuse tail;
// the free field (T60 0) is the renderer without a room. Each trial hears
// the head still, then turned by kDefaultResolvingTurnDeg: at each pose
// several consecutive blocks of 0.1 s localised as one signal (./beft bench
// hearing: 8, so that a trial hears about a short sentence, as theirs do),
// or one, as the audio expert localises each block.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "lib/hearing/binaural_renderer.hpp"
#include "lib/hearing/block_localiser.hpp"
#include "lib/hearing/room_model.hpp"
#include "lib/hearing/trials/stimuli.hpp"

namespace beft::hearing::trials {

struct RoomFigures {
  double t60_s = 0;           // asked for
  double t60_measured_s = 0;  // Schroeder T30 of the rendered response (0 in the free field)
  std::optional<double> drr_db;  // direct (to 2.5 ms after it) over the rest; none in the free field
  int sources = 0;            // simultaneous talkers
  int trials = 0;
  int turns = 1;              // head turns heard (poses: one more)
  int blocks_per_pose = 1;    // consecutive 0.1 s blocks heard at each pose
  double within_5deg = 0;     // share of talkers with one of the N strongest peaks within 5 deg, after the turn
  double median_error_deg = 0;  // median over talkers of the nearest of those peaks, after the turn
  // Share of talkers heard at their mirror image: no peak within 10 deg of
  // the talker, one within 10 deg of its mirror image that no other talker
  // accounts for (none within 10 deg of that peak); the first block alone.
  double front_back_static = 0;
  double front_back_after_turn = 0;  // the same after the turn
};

// Blocks heard at each pose by ./beft bench hearing: 0.8 s before the turn
// and 0.8 s after it, about a short sentence.
inline constexpr int kSentenceBlocksPerPose = 8;

// The room of one T60 (0: none): 16 x 12 x 4 m, listener at (6, 5, 1.6).
struct TrialRoom {
  double t60_s = 0;
  std::unique_ptr<RoomModel> model;  // null in the free field
};
TrialRoom trialRoom(double t60_s, const HrirSet& hrirs, int reflection_order = 2);
// Its inside dimensions [m] and where the head stands.
inline constexpr double kRoomX = 16, kRoomY = 12, kRoomZ = 4;
Eigen::Vector3d trialListener();

class RoomTrials {
 public:
  // The talkers: the scenario sounds talk, help and voice_radio. Throws
  // std::runtime_error if the KEMAR responses or a sound cannot be read.
  RoomTrials(const BinauralRenderer& renderer, BlockLocaliser localiser,
             const std::string& sounds_dir = scenarioSoundsDir());

  // `turns` head turns of kDefaultResolvingTurnDeg, all CCW: blocks_per_pose
  // consecutive blocks heard before them and as many after each, the blocks
  // of one pose localised as one signal, the poses pooled (the figures after
  // the turn are after the last).
  RoomFigures run(const TrialRoom& room, int sources, int trials, uint64_t seed, int turns = 1,
                  int blocks_per_pose = 1);

 private:
  // A first sample from which every talker speaks at every pose: the RMS of
  // what it says while the head listens there (blocks_per_pose blocks) above 0.05.
  int64_t momentAllSpeak(const std::vector<int>& talkers, int sources, int turns, int blocks_per_pose,
                         std::mt19937_64& random) const;
  // What the ears hear at each pose (the head still, then after each turn),
  // blocks_per_pose consecutive blocks each, one after the other.
  std::vector<StereoBlock> hearPoses(BlockRequest request, int64_t first, int turns, int blocks_per_pose) const;
  const BinauralRenderer& renderer_;
  BlockLocaliser localiser_;
  std::vector<std::vector<float>> talkers_;
  std::vector<SourceSignal> signals_;
};

// The response of a room to an impulse 1.5 m ahead of the listener (both ears).
StereoBlock roomImpulseResponse(const BinauralRenderer& renderer, const TrialRoom& room, double seconds);

}  // namespace beft::hearing::trials

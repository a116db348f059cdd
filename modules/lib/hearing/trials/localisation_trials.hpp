// Trials of the localiser on ear signals through the KEMAR responses the
// simulation renders with, against its templates from the MIT KEMAR (a
// different head), 2 m away. Each trial hears two blocks of 0.1 s: the head
// still, then turned by kDefaultResolvingTurnDeg; the figures after the turn
// come from both blocks pooled (BlockLocaliser::localise(blocks)). The statistical tests and
// ./beft bench hearing both take their figures from here; a seed fixes them.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "lib/hearing/block_localiser.hpp"
#include "lib/hearing/trials/stimuli.hpp"

namespace beft::hearing::trials {

struct OneSourceFigures {
  int trials = 0;
  int unheard = 0;                         // trials in which a block gave no peak
  double median_error_folded_deg = 0;      // first block, front-back folded
  double median_error_after_turn_deg = 0;  // both blocks pooled across the turn
  int counted = 0;                         // trials whose mirror image is another direction (> 20 deg away)
  double front_back_static = 0;            // share of those confused without turning
  double front_back_after_turn = 0;        // share of those confused after the turn
};

struct TwoSourceFigures {
  int sources = 0;
  double found_after_turn = 0;  // share within 10 deg of one of the two strongest peaks of both blocks pooled
  double found_folded = 0;      // the same, front-back folded
};

class LocalisationTrials {
 public:
  // The sounds: white and pink noise, then the scenario sounds talk, help,
  // voice_radio, siren, engine and fire from `sounds_dir`. Throws
  // std::runtime_error if the KEMAR responses or a sound cannot be read.
  explicit LocalisationTrials(BlockLocaliser localiser, const std::string& sounds_dir = scenarioSoundsDir());

  // One source per trial (white, pink, talk and help in turn) at a random whole-degree azimuth.
  OneSourceFigures oneSource(int trials, uint64_t seed);
  // Two different sounds per trial at whole-degree azimuths at least 30 deg apart.
  TwoSourceFigures twoSources(int trials, uint64_t seed);

  // The localiser's CPU time per block over every trial so far [ms].
  double localiseMsPerBlock() const { return blocks_ > 0 ? 1e3 * localise_seconds_ / blocks_ : 0; }

 private:
  struct Heard {
    BlockLocalisation before;      // the first block alone: front-back ambiguous
    BlockLocalisation after_turn;  // both blocks pooled in the frame of the turned head
  };
  Heard hear(std::vector<PlacedSound> sounds, uint64_t seed);
  BlockLocalisation localise(const std::vector<EarBlock>& blocks);

  KemarEars ears_;
  BlockLocaliser localiser_;
  std::vector<std::pair<std::string, std::vector<float>>> sounds_;
  double localise_seconds_ = 0;
  int64_t blocks_ = 0;
};

}  // namespace beft::hearing::trials

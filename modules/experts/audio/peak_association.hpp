// Which of a block's localised peaks each sounding object is given.
//
// The spectrum tells a voice from a siren, but not one siren from another:
// a district sounds with several sirens, talkers and engines at once, and
// each block yields a few peaks, mostly of the nearest sources. Giving a
// peak to whichever same-sounding object heard something like it before
// lets the objects hop between sources and mix their bearings. So peaks are
// gated by each object's own track first (gated nearest-neighbour
// association, Bar-Shalom & Fortmann 1988, "Tracking and Data Association",
// ch. 3): an object heard recently (live) takes only a peak within
// gate_deg of the bearing its track predicts, the closest best; a peak that
// a live object could have taken is never given to another object of the
// same sound (it is that source heard twice); only the peaks left start or
// resume an object not heard recently: one whose track predicts that
// bearing first (the same source heard again), then one never heard, and
// last one last heard elsewhere, whose track then starts afresh (another
// source of the same sound).
#pragma once

#include <string>
#include <vector>

#include "lib/hearing/band_signature.hpp"
#include "lib/hearing/block_localiser.hpp"

namespace beft::audio {

// One sounding object as the expert hears it this tick.
struct SoundingObject {
  std::string id;
  const hearing::BandSignature* signature = nullptr;  // of its sound; null: cannot be told apart
};

// What an object's track predicts.
struct TrackPrediction {
  bool heard = false;          // the object was ever given a peak
  bool live = false;           // ... within the last live time
  std::vector<double> bearings_deg;  // the world bearings it is expected at now (heard only; two while
                                     // front and back are not told apart)
};

struct AssociationConfig {
  double min_similarity = 0.6;   // a peak whose spectrum matches no sounding object this well is not assigned
  double gate_deg = 30;          // a live object takes only a peak this close to its predicted bearing
  double mirror_deg = 24;        // a second peak this close to the front-back mirror of the first is the same source
  double agreement_weight = 0.2; // a live pair scores similarity + this * (1 - distance / gate)
  double preference_weight = 0.05;  // a left peak: similarity + this * (2 + agreement: resumes, 1: never heard, 0)
};

// The peaks given to one object (head-relative azimuths), and whether its
// track starts afresh (a source of the same sound elsewhere).
struct ObjectPeaks {
  std::vector<double> azimuths_deg;
  bool restart = false;
};

// One entry per sounding object, in their order; `predictions` likewise.
std::vector<ObjectPeaks> associatePeaks(const std::vector<hearing::LocalisedPeak>& peaks, double head_yaw_deg,
                                        const std::vector<SoundingObject>& sounding,
                                        const std::vector<TrackPrediction>& predictions,
                                        const AssociationConfig& config = AssociationConfig{});

}  // namespace beft::audio

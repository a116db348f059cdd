// What the audio expert knows of the sounding objects from the ear signals
// alone (--param acoustics=binaural). Each block of EARS is localised
// (hearing::BlockLocaliser: a posterior over head-relative azimuth and its
// peaks, each with the band spectrum of what voted for it); each peak is
// given to the sounding object whose sound has the most similar spectrum
// (ties broken by the direction the object was heard in before). Objects
// of one sound (the same signature) cannot be told apart that way: among
// them, a peak from the direction of one that vision has placed (or from its
// front-back mirror image) is that one's; without this the peaks of the
// sirens already seen would keep pulling the estimates of the ones not seen
// yet towards them. And any seen object takes only the peaks from where it
// was seen: once the robot has moved away, another source of a like
// spectrum, nearer and louder, would pull its estimate towards the robot.
// Each object keeps
//  - a posterior over the world direction it is heard in: the block's
//    posterior near its peaks, turned into the world frame, adds bounded
//    evidence to what was heard before, which fades. When the head turns, the
//    mirror image of the true direction (front-back: interaural cues are the
//    same at a and 180 - a) moves the other way in the world frame and dies
//    out while the true direction keeps agreeing (Wallach 1940);
//  - bearing lines from the places it was heard from clearly, whose crossing
//    (bearing_triangulation.hpp) gives the distance once the robot has moved
//    enough; before that the estimate lies default_distance_m along the
//    bearing;
//  - the best crossing so far (the fix), kept after its lines have aged out
//    while the direction it is heard in still points at it: far from a
//    source, where bearings no longer cross, the estimate stays where the
//    lines crossed instead of falling back to default_distance_m from the
//    robot. A new crossing takes the fix's place only when its error
//    (crossingError) is no larger than the fix's, grown by fix_aging_mps
//    since it was made: lines from far away, or from places that see the
//    source at nearly one angle, cross where a small error of their
//    bearings puts them, and must not replace a crossing made up close. A
//    clear direction that misses the fix by more than fix_agreement_deg for
//    fix_disagreement_s (the source moved, or the crossing was wrong) drops
//    it, and the lines heard before that miss began, which made it; a
//    moment's miss (a mirror image, a peak of another source) does not.
// When an object's direction stays front-back ambiguous, a head turn is
// asked for (wantsHeadTurn).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <beft/binaural_block_t.hpp>

#include "lib/hearing/azimuth_posterior.hpp"
#include "lib/hearing/band_signature.hpp"
#include "experts/audio/bearing_triangulation.hpp"
#include "lib/hearing/block_localiser.hpp"

namespace beft::audio {

struct HearingConfig {
  double min_similarity = 0.6;       // a peak whose spectrum matches no sounding object this well is not assigned
  double seen_explains_deg = 10;     // a seen object takes only peaks this near its seen direction (or its mirror) [deg]; 0: off
  double peak_half_width_deg = 12;   // the part of the block's posterior that belongs to a peak
  double forgetting = 0.1;           // per block: this share of the evidence gathered so far fades
  double evidence_per_block = 2.0;   // one block multiplies a direction's odds by at most 1 + this
  double clear_mass = 0.5;           // a bearing line is kept when this share of the posterior lies within 10 deg
  double line_spacing_m = 0.3;       // lines from places at least this far apart
  int max_lines = 40;                // the newest lines kept per object
  double line_max_age_s = 30;        // older lines are dropped (the source may have moved)
  double default_distance_m = 4;     // distance of an estimate before triangulation [m]
  double fix_agreement_deg = 15;     // a kept fix stays while the heard direction is this near it [deg]
  double fix_near_m = 2;             // nearer than this to the fix, its direction is not checked [m]
  double fix_disagreement_s = 2;     // the fix is dropped once the clear direction has missed it this long [s]
  double bearing_sd_deg = 3;         // a clear bearing's error, for a crossing's error (crossingError) [deg]
  double fix_aging_mps = 0.05;       // a kept fix's error grows this much per second: its source may have moved [m/s]
  double turn_deg = 20;              // the head turn that resolves front and back
  double turn_interval_s = 3;        // at most one head turn per this time
  TriangulationLimits triangulation;
};

// One sounding object as the expert hears it this tick.
struct SoundingObject {
  SoundingObject(std::string object_id, const hearing::BandSignature* sound_signature,
                 std::optional<Eigen::Vector2d> seen_position = std::nullopt)
      : id(std::move(object_id)), signature(sound_signature), seen_at(std::move(seen_position)) {}
  std::string id;
  const hearing::BandSignature* signature = nullptr;  // of its sound (objects of one sound share it); null: cannot be told apart
  std::optional<Eigen::Vector2d> seen_at;             // where vision placed it, if it was seen (world frame [m])
};

struct HeardEstimate {
  Eigen::Vector2d position;  // world frame [m]
  bool triangulated = false;
  double bearing_deg = 0;    // world direction from where it was last heard [deg]
};

class HeardSources {
 public:
  explicit HeardSources(const HearingConfig& config = HearingConfig{}) : config_(config) {}

  // One block: its localisation, the head's pose (block message) and the
  // objects that sound now.
  void hear(const hearing::BlockLocalisation& heard, const binaural_block_t& block,
            const std::vector<SoundingObject>& sounding);

  // The object's position estimate, if it was ever heard.
  std::optional<HeardEstimate> estimate(const std::string& id) const;

  // The head yaw (relative to the platform, within +-limit) to turn to, if an
  // object heard this tick is front-back ambiguous and no turn was asked for
  // within turn_interval_s; the object's id in `object_id`.
  std::optional<double> wantsHeadTurn(double head_yaw_deg, double limit_deg, int64_t utime, std::string* object_id);

  const HearingConfig& config() const { return config_; }

 private:
  struct Track {
    std::array<double, hearing::AzimuthPosterior::kBins> log_evidence{};  // per world bearing
    hearing::AzimuthPosterior world;  // over world bearing, CCW from +x: from log_evidence
    Eigen::Vector2d heard_from = Eigen::Vector2d::Zero();
    std::vector<std::pair<int64_t, BearingLine>> lines;  // (utime, line)
    std::optional<Eigen::Vector2d> fix;                  // the best crossing of the lines, while heard there
    double fix_error_m = 0;                              // its crossingError when it was made [m]
    int64_t fix_utime = 0;                               // when it was made [us]
    int64_t disagreeing_since = -1;                      // since when the clear direction misses the fix [us], -1: it does not
    int64_t last_heard_tick = -1;
  };
  void update(Track& track, const hearing::AzimuthPosterior& heard_world, const binaural_block_t& block);
  void keepFix(Track& track, bool clear, int64_t utime) const;
  bool fixAgrees(const Track& track, bool clear) const;

  HearingConfig config_;
  std::map<std::string, Track> tracks_;
  int64_t last_turn_utime_ = -1;
  int64_t last_tick_ = -1;
  double last_head_yaw_ = 0;  // world heading of the nose in the last block [deg]
};

}  // namespace beft::audio

// The fusion expert's logic (high level): one hypothesis per object that
// either modality has perceived, kept for the rest of the run (an object
// heard once stays a hypothesis when it falls silent).
//
// Rules, per hypothesis:
//  - Evidence memory: per modality, the labels of the tick with the highest
//    perceptibility so far (ties: the newer one). Visual evidence counts only
//    when the object has visible pixels; acoustic evidence whenever AUDIO
//    reports the object.
//  - Fused confidence of category k_j: the perceptibility-weighted average of
//    the two memories, (vP* vL_j + aP* aL_j) / (vP* + aP*); a modality that
//    never perceived the object has weight 0.
//  - seen: some tick had v_P >= seen_threshold with visible pixels (sticky);
//    heard: AUDIO has reported it (sticky).
//  - seen_as / heard_as: the best category of the visual / acoustic memory
//    (empty while not seen / not heard).
//  - verified: heard and seen with seen_as == heard_as; falsified: heard and
//    seen with seen_as != heard_as (the radio that sounds like a person but
//    looks like a siren). settled_utime: when one of them first held.
//  - position: where vision last saw it (its ground-truth position at the
//    last tick with visible pixels: vision localises what it sees), else the
//    latest acoustic estimate p_hat.
//  - restore(): after a restart, the hypotheses last published come back
//    with their flags, times and position; their published fused
//    confidences (weighted by their best value) stand in for a modality with
//    no new evidence since, and seen_as / heard_as stay as published until
//    that modality perceives the object again.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/labels_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/visual_percepts_t.hpp>

#include "lib/expert/id_index.hpp"

namespace beft::fusion {

// How the best visual and the best acoustic evidence combine into one
// confidence per category. The paper leaves it open; these are this
// project's rules (README: "Fusion: this project's rules").
enum class FusionRule {
  WeightedMean,  // sum(P_m * L_m) / sum(P_m): the clearer modality counts more (default)
  Mean,          // the plain mean of the modalities' L_m
  Clearest,      // the L_m of the modality with the highest perceptibility
};

struct FusionConfig {
  // v_P from which an object counts as seen [0..1]. With v_P = g_d * v_o,
  // g_d(10 m) = 0.5: at the default nothing beyond 10 m counts as seen.
  double seen_threshold = 0.5;
  FusionRule rule = FusionRule::WeightedMean;
};

// One tick's inputs; any of the percept inputs may be missing (null) when
// that expert did not deliver, the scene may not.
struct TickEvidence {
  const scene_objects_t* scene = nullptr;
  const visual_percepts_t* vision = nullptr;
  const labels_t* visual_labels = nullptr;
  const acoustic_percepts_t* audio = nullptr;
  const labels_t* acoustic_labels = nullptr;
};

class HypothesisFusion {
 public:
  explicit HypothesisFusion(const FusionConfig& config = {}) : config_(config) {}

  // Folds in the evidence of one tick (stamped with the scene's utime).
  void update(const TickEvidence& evidence);
  // Starts from hypotheses published earlier (before a restart); only when
  // no hypothesis exists yet.
  void restore(const hypotheses_t& previous);
  // Every hypothesis so far, in order of first perception (ties: scenario order).
  hypotheses_t hypotheses(int64_t utime, int64_t tick) const;
  // The same, written over `out`: the strings and arrays of the previous
  // tick's list are reused (hundreds of hypotheses a tick would otherwise be
  // thousands of allocations).
  void writeHypotheses(int64_t utime, int64_t tick, hypotheses_t& out) const;
  std::size_t size() const { return hypotheses_.size(); }

 private:
  struct Evidence {
    double perceptibility = 0;
    std::vector<std::string> categories;
    std::vector<double> confidence;
  };
  struct Position {
    double x = 0, y = 0, z = 0;
    bool located = true;  // false: a point along a heard bearing at an assumed range
  };
  struct Hypothesis {
    std::string object_id;
    std::optional<Evidence> visual, acoustic;  // best evidence so far
    std::optional<Evidence> restored;          // fused confidences published before a restart
    std::string restored_seen_as, restored_heard_as;
    std::optional<Position> visual_position, acoustic_position;
    bool seen = false, heard = false;
    int64_t first_seen_utime = -1, first_heard_utime = -1, settled_utime = -1;
  };

  Hypothesis& hypothesisFor(const std::string& object_id);
  // Every field of `out` is written.
  void writeMessage(const Hypothesis& h, const std::vector<std::string>& categories, hypothesis_t& out) const;

  FusionConfig config_;
  std::vector<std::string> categories_;  // of the latest scene
  std::vector<Hypothesis> hypotheses_;   // only ever appended to
  std::unordered_map<std::string, std::size_t> hypothesis_index_;  // object id -> place in hypotheses_
  expert::IdPositions<scene_object_t> scene_positions_;           // where each object of the scene is in its list
};

}  // namespace beft::fusion

// Optional noise on the acoustic position estimate p_hat: a horizontal
// Gaussian offset whose spread grows as the acoustic perceptibility a_P falls,
// sigma = max_sigma * (1 - a_P). Deterministic: the offset is a function of
// (seed, tick, object id) only, so a run with the same seed repeats exactly.
#pragma once

#include <cstdint>
#include <string>

#include <Eigen/Core>

namespace beft::audio {

struct PositionNoiseConfig {
  bool enabled = false;     // off: p_hat is the true position
  double max_sigma = 2.0;   // spread at a_P = 0 [m]
  uint64_t seed = 0;
};

// The (dx, dy) offset [m] for one object at one tick.
Eigen::Vector2d positionNoise(const PositionNoiseConfig& config, int64_t tick, const std::string& object_id,
                              double acoustic_perceptibility);

}  // namespace beft::audio

#include "experts/audio/position_noise.hpp"

#include <algorithm>
#include <cmath>

namespace beft::audio {

namespace {

// FNV-1a: a string hash that is the same on every platform (std::hash is not).
uint64_t hashString(const std::string& text) {
  uint64_t hash = 1469598103934665603ULL;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ULL;
  }
  return hash;
}

// splitmix64: one step of a small, well-mixed generator.
uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// Uniform in (0, 1].
double uniform(uint64_t& state) { return (static_cast<double>(splitmix64(state) >> 11) + 1.0) / 9007199254740992.0; }

}  // namespace

Eigen::Vector2d positionNoise(const PositionNoiseConfig& config, int64_t tick, const std::string& object_id,
                              double acoustic_perceptibility) {
  if (!config.enabled) return Eigen::Vector2d::Zero();
  const double sigma = config.max_sigma * (1.0 - std::clamp(acoustic_perceptibility, 0.0, 1.0));
  uint64_t state = config.seed ^ (hashString(object_id) + 0x9E3779B97F4A7C15ULL * static_cast<uint64_t>(tick));
  // Box-Muller: two independent standard normal values.
  const double radius = std::sqrt(-2.0 * std::log(uniform(state)));
  const double angle = 2.0 * M_PI * uniform(state);
  return {sigma * radius * std::cos(angle), sigma * radius * std::sin(angle)};
}

}  // namespace beft::audio

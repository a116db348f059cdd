// The microphones' own noise: Gaussian, independent in each ear, and a pure
// function of (seed, absolute sample index), so any block, rendered alone or
// as part of a longer span, in any process, gets the same noise.
#pragma once

#include <cstdint>

namespace beft::hearing {

// Adds noise of standard deviation `rms` to left[0..n) and right[0..n),
// whose first sample is absolute sample `first_sample`.
void addSensorNoise(uint64_t seed, int64_t first_sample, int n, double rms, float* left, float* right);

}  // namespace beft::hearing

// Reading a looped mono signal between its samples: the signal repeats for
// ever in both directions (index i and i + length are the same sample,
// negative indices included).
#pragma once

#include <cstdint>
#include <vector>

namespace beft::hearing {

// The signal at position index + fraction (fraction in [0, 1)), by 4-point
// cubic (Catmull-Rom) interpolation: at the worst (half-sample) fraction it
// loses 1.1 dB at a quarter of the sample rate, where linear interpolation
// loses 3 dB. Positions are split into an integer index and a fraction by
// the caller so that the same position gives the same value however it was
// reached. 0 for an empty signal.
float readLooped(const std::vector<float>& signal, int64_t index, float fraction);

// The same for an index already wrapped into [0, signal.size()): no
// division (signal must not be empty).
float readLoopedWrapped(const std::vector<float>& signal, int64_t wrapped_index, float fraction);

// out[i] = gain * readLooped(signal, first_index + i, fraction), i < count;
// the same values, computed without a division per sample.
void readLoopedRun(const std::vector<float>& signal, int64_t first_index, float fraction, float gain, int count,
                   float* out);

}  // namespace beft::hearing

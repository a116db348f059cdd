// How a source's looped signal is read as it arrives at the head: shared by
// the direct sound (binaural_renderer.cpp) and the room (room_rendering.cpp).
// Internal to the renderer.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "lib/hearing/looped_signal.hpp"

namespace beft::hearing::detail {

// Where and how loud a source is for one head pose.
struct SourceView {
  double azimuth_deg;
  double gain;           // level / r
  double delay_samples;  // r / c
};

// Position index + fraction of the signal heard at absolute sample n when
// it is read `shift` samples later (shift = advance - delay): the split
// depends on shift alone, so a sample's value does not depend on the block.
struct ReadPosition {
  int64_t offset;  // added to n
  float fraction;
};
inline ReadPosition splitShift(double shift) {
  const double whole = std::floor(shift);
  return {static_cast<int64_t>(whole), static_cast<float>(shift - whole)};
}

// Share of the way from the previous pose to the current one at absolute
// sample n, for a block of `total` samples from `first`: 1/total at the
// block's first sample, 1 at its last, negative before the block.
inline double progressAt(int64_t n, int64_t first, int total) { return static_cast<double>(n - first + 1) / total; }

// A source's signal as it arrives at the head centre while the head stands
// still, from absolute sample segment_first on.
inline void readStill(const std::vector<float>& signal, const SourceView& view, double read_advance, int64_t segment_first,
               int segment_length, float* segment) {
  const ReadPosition read = splitShift(read_advance - view.delay_samples);
  readLoopedRun(signal, segment_first + read.offset, read.fraction, static_cast<float>(view.gain), segment_length,
                segment);
}

// The same while the head moves from the pose `before` to `after` over the
// block of `total` samples from `first`. The delay and gain move linearly
// over the block; before it (the history the filters need), they continue
// the same motion backwards, at most one block's worth, which is what the
// previous block rendered when the head moved steadily: walking towards a
// source at 1 m/s, holding the delay there instead put a 2-sample phase jump
// at each block's start. The read index moves by 0 to 2 samples from one
// sample to the next: a cursor kept wrapped saves a division per sample.
inline void readMoving(const std::vector<float>& signal, const SourceView& before, const SourceView& after,
                double read_advance, int64_t segment_first, int segment_length, int64_t first, int total,
                float* segment) {
  const int64_t length = static_cast<int64_t>(signal.size());
  int64_t index = 0, cursor = 0;
  for (int j = 0; j < segment_length; ++j) {
    const int64_t n = segment_first + j;
    const double u = std::clamp(progressAt(n, first, total), -1.0, 1.0);
    const double delay = before.delay_samples + u * (after.delay_samples - before.delay_samples);
    const double gain = std::max(0.0, before.gain + u * (after.gain - before.gain));
    const ReadPosition read = splitShift(read_advance - delay);
    const int64_t next = n + read.offset;
    if (j == 0 || next - index > 2 * length || index - next > 2 * length) {
      cursor = ((next % length) + length) % length;
    } else {
      cursor += next - index;
      while (cursor >= length) cursor -= length;
      while (cursor < 0) cursor += length;
    }
    index = next;
    segment[j] = static_cast<float>(gain) * readLoopedWrapped(signal, cursor, read.fraction);
  }
}

}  // namespace beft::hearing::detail

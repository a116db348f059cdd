// How a source's looped signal is read as it arrives at the head: shared by
// the direct sound (binaural_renderer.cpp) and the room (room_rendering.cpp).
// Internal to the renderer.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <vector>

#include "lib/hearing/fft_convolver.hpp"
#include "lib/hearing/looped_signal.hpp"

namespace beft::hearing::detail {

constexpr double kPi = 3.14159265358979323846;
// Output samples per FFT: a 0.1 s block is one chunk; a long span is cut
// into chunks so the transforms stay small (overlap-save).
constexpr int kMaxChunk = 16384;

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

// The chunk of a turning head, from absolute sample chunk_first: the ears of
// the previous pose blended into those of the current one by a raised cosine
// w = (1 - cos(pi u)) / 2, u = (j + 1) / total, from 0 to 1, the cosine by
// rotating a phasor, one step per sample; written into the ears (the direct
// sound) or added to them (the room's part).
inline void blendPoses(const Samples (&outputs)[2][2], int history, int chunk, int64_t chunk_first, int64_t first,
                       int total, float* const ears[2], bool add) {
  const std::complex<double> step = std::polar(1.0, kPi / total);
  std::complex<double> phasor = std::polar(1.0, kPi * progressAt(chunk_first, first, total));
  for (int j = 0; j < chunk; ++j) {
    const float w = static_cast<float>(0.5 - 0.5 * phasor.real());
    phasor *= step;
    for (int ear = 0; ear < 2; ++ear) {
      const float blended = (1 - w) * outputs[0][ear][history + j] + w * outputs[1][ear][history + j];
      ears[ear][j] = add ? ears[ear][j] + blended : blended;
    }
  }
}

}  // namespace beft::hearing::detail

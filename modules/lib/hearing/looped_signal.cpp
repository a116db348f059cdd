#include "lib/hearing/looped_signal.hpp"

#include <algorithm>

namespace beft::hearing {

namespace {

int64_t wrapIndex(int64_t index, int64_t length) {
  const int64_t wrapped = index % length;
  return wrapped < 0 ? wrapped + length : wrapped;
}

// Catmull-Rom through y1 (t = 0) and y2 (t = 1), as weights of the four
// samples (every reading of the same fraction rounds the same way).
struct Weights {
  float w0, w1, w2, w3;
};
Weights catmullRomWeights(float t) {
  const float t2 = t * t, t3 = t2 * t;
  return {-0.5f * t3 + t2 - 0.5f * t, 1.5f * t3 - 2.5f * t2 + 1.0f, -1.5f * t3 + 2.0f * t2 + 0.5f * t,
          0.5f * t3 - 0.5f * t2};
}
float apply(const Weights& w, float y0, float y1, float y2, float y3) {
  return w.w0 * y0 + w.w1 * y1 + w.w2 * y2 + w.w3 * y3;
}

}  // namespace

float readLooped(const std::vector<float>& signal, int64_t index, float fraction) {
  const int64_t length = static_cast<int64_t>(signal.size());
  if (length == 0) return 0.0f;
  const auto at = [&](int64_t offset) { return signal[static_cast<std::size_t>(wrapIndex(index + offset, length))]; };
  return apply(catmullRomWeights(fraction), at(-1), at(0), at(1), at(2));
}

float readLoopedWrapped(const std::vector<float>& signal, int64_t wrapped_index, float fraction) {
  const int64_t length = static_cast<int64_t>(signal.size());
  const auto step = [length](int64_t i) { return i >= length ? i - length : i; };
  const int64_t i0 = wrapped_index == 0 ? length - 1 : wrapped_index - 1;
  const int64_t i2 = step(wrapped_index + 1), i3 = step(i2 + 1);
  const float* s = signal.data();
  return apply(catmullRomWeights(fraction), s[i0], s[wrapped_index], s[i2], s[i3]);
}

void readLoopedRun(const std::vector<float>& signal, int64_t first_index, float fraction, float gain, int count,
                   float* out) {
  const int64_t length = static_cast<int64_t>(signal.size());
  if (length == 0) {
    std::fill(out, out + std::max(count, 0), 0.0f);
    return;
  }
  // Where the four samples lie in order without wrapping, one vectorisable
  // loop; round the loop's end, sample by sample.
  const Weights w = catmullRomWeights(fraction);
  const float* s = signal.data();
  int64_t index = wrapIndex(first_index, length);
  int i = 0;
  while (i < count) {
    if (index >= 1 && index + 2 < length) {
      const int run = static_cast<int>(std::min<int64_t>(count - i, length - 2 - index));
      const float* y = s + index;
      float* o = out + i;
      for (int k = 0; k < run; ++k) o[k] = gain * apply(w, y[k - 1], y[k], y[k + 1], y[k + 2]);
      i += run;
      index += run;
    } else {
      const auto at = [&](int64_t offset) { return s[wrapIndex(index + offset, length)]; };
      out[i] = gain * apply(w, at(-1), at(0), at(1), at(2));
      ++i;
      if (++index == length) index = 0;
    }
  }
}

}  // namespace beft::hearing

#include "lib/hearing/sensor_noise.hpp"

#include <cmath>

namespace beft::hearing {

namespace {

// SplitMix64's output function: a well-mixed 64-bit hash of a counter.
uint64_t mix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A uniform in (0, 1] from the top 53 bits.
double unit(uint64_t bits) { return (static_cast<double>(bits >> 11) + 1.0) * (1.0 / 9007199254740992.0); }

}  // namespace

void addSensorNoise(uint64_t seed, int64_t first_sample, int n, double rms, float* left, float* right) {
  if (!(rms > 0) || n <= 0) return;
  const uint64_t stream = mix(seed);
  for (int i = 0; i < n; ++i) {
    // Marsaglia's polar method: a point drawn in the unit disc gives the two
    // ears' independent normals, without the sine and cosine of Box-Muller.
    // Each draw is the next hash of the sample's counter, so the result
    // depends on (seed, sample) alone.
    uint64_t state = stream ^ static_cast<uint64_t>(first_sample + i) * 0xd1342543de82ef95ULL;
    double x, y, radius2;
    do {
      state = mix(state);
      x = 2 * unit(state) - 1;
      state = mix(state);
      y = 2 * unit(state) - 1;
      radius2 = x * x + y * y;
    } while (radius2 >= 1 || radius2 == 0);
    const double scale = rms * std::sqrt(-2.0 * std::log(radius2) / radius2);
    left[i] += static_cast<float>(x * scale);
    right[i] += static_cast<float>(y * scale);
  }
}

}  // namespace beft::hearing

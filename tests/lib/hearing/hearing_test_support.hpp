// What the hearing tests share: the KEMAR set (the tests that need it are
// skipped where its package is not installed), white noise, static scenes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lib/hearing/binaural_renderer.hpp"
#include "lib/hearing/hrir_set.hpp"

namespace beft::hearing::test {

bool kemarInstalled();
// Loaded once; call only when kemarInstalled().
const HrirSet& kemar();
const BinauralRenderer& kemarRenderer();

// Gaussian white noise of unit RMS, seconds long at 44.1 kHz.
SourceSignal whiteNoise(double seconds, uint64_t seed);
// A sine of frequency_hz and amplitude 1.
SourceSignal sine(double frequency_hz, double seconds);

// One source at `azimuth_deg` (counter-clockwise, 0 = ahead) and
// `distance` from a head at the origin facing +x, rendered without noise.
BlockRequest staticScene(const SourceSignal& signal, double azimuth_deg, double distance, int64_t first_sample,
                         int num_samples, double occlusion = 0);

// Largest |x[i + 1] - x[i]|.
double largestStep(const std::vector<float>& x);

}  // namespace beft::hearing::test

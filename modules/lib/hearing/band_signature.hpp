// A sound's spectral fingerprint: its energy per band of an analysis layout.
// The localiser gives each peak the signature of the time-frequency bins that
// voted for it; a known sound's long-term signature says which sound that is
// when the sounds of a scene differ in spectrum (a siren's two tones, an
// engine's rumble, a voice's formants).
#pragma once

#include <vector>

#include "lib/hearing/analysis_layout.hpp"

namespace beft::hearing {

struct BandSignature {
  std::vector<double> band_energy;  // per band of the layout, >= 0, any common scale
};

// The long-term band spectrum of a mono sound (Hann frames of the layout's
// duration, half overlapping), at its own sample rate: bins are summed into
// the layout's bands by frequency; bands above its Nyquist get nothing. Sounds
// shorter than a frame are zero-padded. Throws std::invalid_argument on a
// non-finite sample or a rate <= 0.
BandSignature signatureOfSound(const std::vector<float>& samples, double sample_rate, const AnalysisLayout& layout);

// How alike two signatures' spectral shapes are, from -1 to 1 (1: the same
// shape at any level): the correlation of their band levels in dB, each
// floored 50 dB below its own loudest band so that empty bands compare as
// equally empty. 0 if either is empty or silent or they differ in length.
double signatureSimilarity(const BandSignature& a, const BandSignature& b);

}  // namespace beft::hearing

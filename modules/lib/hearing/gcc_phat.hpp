// The delay between two signals by generalised cross-correlation with phase
// transform (GCC-PHAT; Knapp & Carter 1976): each frequency's cross-spectrum
// keeps only its phase, so every band counts alike whatever its level, and
// the correlation over lags peaks at the delay. Limited to low frequencies,
// where the phase of an ear's delay is not yet ambiguous.
#pragma once

#include <vector>

namespace beft::hearing {

struct DelayEstimate {
  double delay_s = 0;  // > 0: `right` lags `left` (a sound from the left reaches the left ear first)
  double peak = 0;     // the correlation there, 1 for a pure delay, 0 if there was nothing to correlate
};

// Searches |delay| <= max_delay_s over frequencies from the first bin above
// DC to max_hz, to a small fraction of a sample (refined around the best
// whole-sample lag). Signals of different lengths are zero-padded.
DelayEstimate gccPhatDelay(const std::vector<float>& left, const std::vector<float>& right, double sample_rate,
                           double max_hz = 1500, double max_delay_s = 1e-3);

}  // namespace beft::hearing

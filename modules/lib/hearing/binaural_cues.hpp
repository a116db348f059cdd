// The cues a listener reads from two ear signals: interaural time and level
// differences and where the spectrum's weight lies. Used to check the
// renderer and by localisers built on it.
#pragma once

#include <vector>

namespace beft::hearing {

// Lag of the cross-correlation's peak between the ears [ms], searched within
// +-max_lag_ms and refined by a parabola through the peak and its
// neighbours; positive when the left ear hears the sound first (a source on
// the left). 0 for signals of different or zero length.
double interauralTimeDifferenceMs(const std::vector<float>& left, const std::vector<float>& right,
                                  double sample_rate, double max_lag_ms = 1.0);

// How a signal is cut out before its spectrum is taken: Hann for a stretch
// of a longer sound (less leakage), Rectangular for a whole impulse
// response (a window would weigh its onset by where it happens to lie).
enum class Window { Hann, Rectangular };

// Power of the left ear over the right one [dB] in the band [low_hz,
// high_hz); positive when the left ear is louder.
double interauralLevelDifferenceDb(const std::vector<float>& left, const std::vector<float>& right,
                                   double sample_rate, double low_hz = 0, double high_hz = 1e12,
                                   Window window = Window::Hann);

// Power in the band [low_hz, high_hz) of x's spectrum (sum of squared
// magnitudes) [-].
double bandPower(const std::vector<float>& x, double sample_rate, double low_hz, double high_hz,
                 Window window = Window::Hann);

// Power-weighted mean frequency of x's Hann-windowed spectrum [Hz]; 0 for
// silence.
double spectralCentroidHz(const std::vector<float>& x, double sample_rate);

// Root mean square of x [-].
double rms(const std::vector<float>& x);

}  // namespace beft::hearing

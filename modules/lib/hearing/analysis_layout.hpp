// How ear signals are cut into time-frequency bins for localisation: the
// frame length (also the FFT size), the hop between frames, and the bands.
// Templates and localiser are built for one layout; both must use the same.
#pragma once

#include "lib/hearing/frequency_bands.hpp"

namespace beft::hearing {

struct AnalysisLayout {
  double sample_rate = 44100;  // [Hz]
  int frame_size = 1024;       // samples per frame (23 ms), Hann-windowed; also the FFT size
  int hop = 512;               // samples between frame starts: a 0.1 s block gives 7 frames
  double low_hz = 80;          // lowest band edge [Hz]
  // Below this, interaural time (phase) cues; above it, level cues. Near
  // 1.5 kHz the head's ITD of up to 0.7 ms makes the phase ambiguous, and
  // the head starts to shadow the far ear.
  double split_hz = 1500;
  double high_hz = 16000;  // highest band edge [Hz]
  // Interaural phase is compared with the templates' up to here: above the
  // split it is ambiguous within one bin (several azimuths share a phase),
  // but summed over many bins only the true direction agrees in all of them,
  // and a sound that holds the high bins while another holds the low ones
  // still gets its time cues.
  double phase_high_hz = 6000;
  double erb_step = 1.0;   // band width [ERB]

  FrequencyBands bands() const { return FrequencyBands(frame_size, sample_rate, low_hz, high_hz, erb_step, split_hz); }
};

}  // namespace beft::hearing

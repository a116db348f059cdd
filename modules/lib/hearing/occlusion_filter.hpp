// What an obstacle between a source and the ears does to the sound: less
// level and fewer highs (the highs are blocked, the lows bend round it).
#pragma once

#include <vector>

namespace beft::hearing {

struct OcclusionModel {
  // Broadband gain 1 - gain_loss * O_a, linear in amplitude: -8 dB when
  // every line is blocked (the model's a_o = 1 - 0.8 O_a is a
  // perceptibility; here the low-pass below takes the rest of the level).
  double gain_loss = 0.6;
  // Low-pass cut-off falling geometrically (evenly on a log-frequency axis)
  // from open_cutoff_hz at O_a = 0 to blocked_cutoff_hz at O_a = 1.
  double open_cutoff_hz = 20000;
  double blocked_cutoff_hz = 1000;
  // Taps of the linear-phase low-pass (odd): its delay, (taps - 1) / 2
  // samples, is the same at every O_a, and the renderer takes it off the
  // propagation delay.
  int taps = 127;
};

// Gain for occlusion O_a in [0, 1] (clamped).
double occlusionGain(double occlusion, const OcclusionModel& model = {});
// Cut-off [Hz] for occlusion O_a in [0, 1] (clamped).
double occlusionCutoffHz(double occlusion, const OcclusionModel& model = {});
// The low-pass times the gain: a Blackman-windowed sinc of model.taps taps
// whose cut-off (-6 dB) is occlusionCutoffHz, with DC gain occlusionGain.
// The cut-off is kept below 0.45 sample_rate.
std::vector<float> occlusionFilter(double occlusion, double sample_rate, const OcclusionModel& model = {});

}  // namespace beft::hearing

#include "lib/hearing/occlusion_filter.hpp"

#include <algorithm>
#include <cmath>

namespace beft::hearing {

namespace {
constexpr double kPi = 3.14159265358979323846;
double clampUnit(double x) { return std::isfinite(x) ? std::clamp(x, 0.0, 1.0) : 0.0; }
}  // namespace

double occlusionGain(double occlusion, const OcclusionModel& model) {
  return 1 - model.gain_loss * clampUnit(occlusion);
}

double occlusionCutoffHz(double occlusion, const OcclusionModel& model) {
  return model.open_cutoff_hz * std::pow(model.blocked_cutoff_hz / model.open_cutoff_hz, clampUnit(occlusion));
}

std::vector<float> occlusionFilter(double occlusion, double sample_rate, const OcclusionModel& model) {
  const int taps = std::max(1, model.taps | 1);
  const double cutoff = std::min(occlusionCutoffHz(occlusion, model), 0.45 * sample_rate) / sample_rate;  // cycles/sample
  const double centre = (taps - 1) / 2.0;
  std::vector<double> h(taps);
  double sum = 0;
  for (int n = 0; n < taps; ++n) {
    const double x = n - centre;
    const double sinc = x == 0 ? 2 * cutoff : std::sin(2 * kPi * cutoff * x) / (kPi * x);
    const double window =
        taps == 1 ? 1.0 : 0.42 - 0.5 * std::cos(2 * kPi * n / (taps - 1)) + 0.08 * std::cos(4 * kPi * n / (taps - 1));
    h[n] = sinc * window;
    sum += h[n];
  }
  const double gain = occlusionGain(occlusion, model);
  std::vector<float> filter(taps);
  for (int n = 0; n < taps; ++n) filter[n] = static_cast<float>(h[n] / sum * gain);
  return filter;
}

}  // namespace beft::hearing

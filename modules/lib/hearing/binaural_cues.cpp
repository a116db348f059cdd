#include "lib/hearing/binaural_cues.hpp"

#include <cmath>
#include <limits>

#include "lib/hearing/fft_convolver.hpp"

namespace beft::hearing {

namespace {

constexpr double kPi = 3.14159265358979323846;

// |X(k)|^2 of x windowed, k = 0 .. size/2, and the bin width [Hz].
std::vector<double> powerSpectrum(const std::vector<float>& x, double sample_rate, Window window, double& bin_hz) {
  const int n = static_cast<int>(x.size());
  const RealFft fft(fastFftSize(n));
  std::vector<float> windowed(x);
  if (window == Window::Hann)
    for (int i = 0; i < n; ++i)
      windowed[i] = static_cast<float>(x[i] * (0.5 - 0.5 * std::cos(2 * kPi * (i + 0.5) / n)));
  Samples scratch;
  Spectrum spectrum;
  fft.forward(windowed.data(), n, scratch, spectrum);
  std::vector<double> power(fft.bins());
  for (int k = 0; k < fft.bins(); ++k) power[k] = std::norm(std::complex<double>(spectrum[k]));
  bin_hz = sample_rate / fft.size();
  return power;
}

}  // namespace

double interauralTimeDifferenceMs(const std::vector<float>& left, const std::vector<float>& right,
                                  double sample_rate, double max_lag_ms) {
  const int n = static_cast<int>(left.size());
  if (n == 0 || right.size() != left.size()) return 0;
  const int max_lag = std::max(1, static_cast<int>(std::ceil(max_lag_ms * 1e-3 * sample_rate)));
  // correlation(k) = sum_i left[i] right[i + k]: peaks at k = d when the
  // right ear hears the left one's signal d samples later.
  const auto correlation = [&](int k) {
    double sum = 0;
    for (int i = std::max(0, -k); i < std::min(n, n - k); ++i) sum += static_cast<double>(left[i]) * right[i + k];
    return sum;
  };
  std::vector<double> values(2 * max_lag + 1);
  int best = 0;
  for (int k = -max_lag; k <= max_lag; ++k) {
    values[k + max_lag] = correlation(k);
    if (values[k + max_lag] > values[best]) best = k + max_lag;
  }
  double lag = best - max_lag;
  if (best > 0 && best < 2 * max_lag) {
    const double a = values[best - 1], b = values[best], c = values[best + 1];
    const double curvature = a - 2 * b + c;
    if (curvature < 0) lag += 0.5 * (a - c) / curvature;
  }
  return lag / sample_rate * 1e3;
}

double bandPower(const std::vector<float>& x, double sample_rate, double low_hz, double high_hz, Window window) {
  if (x.empty()) return 0;
  double bin_hz = 0;
  const std::vector<double> power = powerSpectrum(x, sample_rate, window, bin_hz);
  double sum = 0;
  for (std::size_t k = 0; k < power.size(); ++k) {
    const double f = k * bin_hz;
    if (f >= low_hz && f < high_hz) sum += power[k];
  }
  return sum;
}

double interauralLevelDifferenceDb(const std::vector<float>& left, const std::vector<float>& right,
                                   double sample_rate, double low_hz, double high_hz, Window window) {
  const double tiny = std::numeric_limits<double>::min();
  return 10 * std::log10((bandPower(left, sample_rate, low_hz, high_hz, window) + tiny) /
                         (bandPower(right, sample_rate, low_hz, high_hz, window) + tiny));
}

double spectralCentroidHz(const std::vector<float>& x, double sample_rate) {
  if (x.empty()) return 0;
  double bin_hz = 0;
  const std::vector<double> power = powerSpectrum(x, sample_rate, Window::Hann, bin_hz);
  double weighted = 0, total = 0;
  for (std::size_t k = 0; k < power.size(); ++k) {
    weighted += k * bin_hz * power[k];
    total += power[k];
  }
  return total > 0 ? weighted / total : 0;
}

double rms(const std::vector<float>& x) {
  if (x.empty()) return 0;
  double sum = 0;
  for (float v : x) sum += static_cast<double>(v) * v;
  return std::sqrt(sum / x.size());
}

}  // namespace beft::hearing

#include "lib/hearing/gcc_phat.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "lib/hearing/fft_convolver.hpp"

namespace beft::hearing {

DelayEstimate gccPhatDelay(const std::vector<float>& left, const std::vector<float>& right, double sample_rate,
                           double max_hz, double max_delay_s) {
  if (!(sample_rate > 0) || !(max_hz > 0) || !(max_delay_s >= 0))
    throw std::invalid_argument("gccPhatDelay needs sample_rate > 0, max_hz > 0 and max_delay_s >= 0");
  if (left.empty() || right.empty()) return {};
  // Long enough that no circular wrap reaches the lags searched.
  const std::size_t needed = left.size() + right.size();
  int size = 64;
  while (static_cast<std::size_t>(size) < needed) size *= 2;
  const RealFft fft(size);
  std::vector<std::complex<float>> spectrum_left, spectrum_right;
  fft.forward(left, spectrum_left);
  fft.forward(right, spectrum_right);

  const double bin_hz = sample_rate / size;
  const int last_bin = std::min(fft.bins() - 1, static_cast<int>(max_hz / bin_hz));
  std::vector<std::complex<double>> phase;  // unit cross-spectrum per bin 1..last_bin
  std::vector<double> omega;                // [rad/s]
  double largest = 0;
  for (int k = 1; k <= last_bin; ++k) {
    const auto c = std::complex<double>(spectrum_left[k]) * std::conj(std::complex<double>(spectrum_right[k]));
    largest = std::max(largest, std::abs(c));
  }
  for (int k = 1; k <= last_bin; ++k) {
    const auto c = std::complex<double>(spectrum_left[k]) * std::conj(std::complex<double>(spectrum_right[k]));
    if (std::abs(c) <= 1e-12 * largest || std::abs(c) == 0) continue;  // no energy: no phase to trust
    phase.push_back(c / std::abs(c));
    omega.push_back(2 * M_PI * k * bin_hz);
  }
  if (phase.empty()) return {};

  // Right = left delayed by d: cross-spectrum |X|^2 e^{i w d}; steering by e^{-i w tau} peaks at tau = d.
  auto correlation = [&](double tau) {
    double sum = 0;
    for (std::size_t i = 0; i < phase.size(); ++i) sum += (phase[i] * std::polar(1.0, -omega[i] * tau)).real();
    return sum / static_cast<double>(phase.size());
  };
  const int max_lag = static_cast<int>(std::floor(max_delay_s * sample_rate));
  int best_lag = 0;
  double best = -2;
  for (int lag = -max_lag; lag <= max_lag; ++lag) {
    const double value = correlation(lag / sample_rate);
    if (value > best) best = value, best_lag = lag;
  }
  // Refine within a sample on each side in 1/32-sample steps, then a parabola through the best three.
  const double step = 1.0 / 32;
  double best_fine = best_lag;
  for (double lag = best_lag - 1; lag <= best_lag + 1 + 1e-9; lag += step) {
    if (std::abs(lag) > max_delay_s * sample_rate) continue;
    const double value = correlation(lag / sample_rate);
    if (value > best) best = value, best_fine = lag;
  }
  const double before = correlation((best_fine - step) / sample_rate);
  const double after = correlation((best_fine + step) / sample_rate);
  const double curvature = before - 2 * best + after;
  double offset = curvature < 0 ? 0.5 * (before - after) / curvature : 0;
  offset = std::clamp(offset, -1.0, 1.0);
  const double delay = std::clamp((best_fine + offset * step) / sample_rate, -max_delay_s, max_delay_s);
  return {delay, best};
}

}  // namespace beft::hearing

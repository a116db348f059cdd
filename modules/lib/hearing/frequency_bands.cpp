#include "lib/hearing/frequency_bands.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace beft::hearing {

double erbNumber(double hz) { return 21.4 * std::log10(1.0 + 0.00437 * hz); }

double hzOfErbNumber(double erb_number) { return (std::pow(10.0, erb_number / 21.4) - 1.0) / 0.00437; }

FrequencyBands::FrequencyBands(int fft_size, double sample_rate, double low_hz, double high_hz, double erb_step,
                               double split_hz)
    : fft_size_(fft_size), sample_rate_(sample_rate) {
  if (fft_size < 2 || !(sample_rate > 0) || !(erb_step > 0) || !(low_hz >= 0) || !(high_hz > low_hz))
    throw std::invalid_argument("frequency bands need fft_size >= 2, sample_rate > 0, erb_step > 0 and "
                                "0 <= low_hz < high_hz");
  high_hz = std::min(high_hz, 0.5 * sample_rate);
  if (split_hz > low_hz && split_hz < high_hz) {
    appendRange(low_hz, split_hz, erb_step);
    appendRange(split_hz, high_hz, erb_step);
  } else {
    appendRange(low_hz, high_hz, erb_step);
  }
  if (bands_.empty())
    throw std::invalid_argument("no FFT bin lies between " + std::to_string(low_hz) + " and " +
                                std::to_string(high_hz) + " Hz");
}

void FrequencyBands::appendRange(double low_hz, double high_hz, double erb_step) {
  const double bin_hz = binHz();
  const int last_bin = fft_size_ / 2;  // Nyquist
  // Bin k covers [k - 1/2, k + 1/2) * bin_hz; a range [low, high) takes the bins whose centre lies in it.
  auto binAt = [&](double hz) { return std::clamp(static_cast<int>(std::ceil(hz / bin_hz)), 0, last_bin + 1); };
  const double first_erb = erbNumber(low_hz), last_erb = erbNumber(high_hz);
  const int steps = std::max(1, static_cast<int>(std::lround((last_erb - first_erb) / erb_step)));
  int start = binAt(low_hz);
  if (!bands_.empty()) start = std::max(start, bands_.back().end_bin);
  const int range_end = high_hz >= 0.5 * sample_rate_ ? last_bin + 1 : binAt(high_hz);
  for (int i = 1; i <= steps; ++i) {
    const int end =
        i == steps ? range_end : binAt(hzOfErbNumber(first_erb + (last_erb - first_erb) * i / steps));
    if (end <= start) continue;  // too narrow for a bin of its own: merged into the next band
    FrequencyBand band;
    band.first_bin = start;
    band.end_bin = end;
    band.low_hz = std::max(0.0, (start - 0.5) * bin_hz);
    band.high_hz = (end - 0.5) * bin_hz;
    band.centre_hz = hzOfErbNumber(0.5 * (erbNumber(band.low_hz) + erbNumber(band.high_hz)));
    bands_.push_back(band);
    start = end;
  }
}

int FrequencyBands::firstBandFrom(double hz) const {
  for (int i = 0; i < size(); ++i)
    if (bands_[static_cast<std::size_t>(i)].centre_hz >= hz) return i;
  return size();
}

}  // namespace beft::hearing

// Frequency bands over the bins of an FFT, spaced evenly on the ERB-number
// scale (Glasberg & Moore): as wide as the ear's own filters, so narrow at low
// frequencies and wide at high ones. The localiser takes its interaural time
// cues from the bands below a split frequency and its level cues above it.
#pragma once

#include <vector>

namespace beft::hearing {

struct FrequencyBand {
  int first_bin = 0, end_bin = 0;  // FFT bins [first_bin, end_bin)
  double low_hz = 0, high_hz = 0, centre_hz = 0;
};

class FrequencyBands {
 public:
  FrequencyBands() = default;
  // Bands about `erb_step` ERB wide from low_hz to high_hz (clamped to
  // Nyquist) over an FFT of fft_size at sample_rate; every band holds at least
  // one bin, so neighbours too narrow for one are merged. With split_hz
  // between the two, a band edge falls on it (the bin nearest to it) and the
  // bands below and above are spaced separately. Throws std::invalid_argument
  // on a range with no bins.
  FrequencyBands(int fft_size, double sample_rate, double low_hz, double high_hz, double erb_step = 1.0,
                 double split_hz = 0);

  const std::vector<FrequencyBand>& bands() const { return bands_; }
  int size() const { return static_cast<int>(bands_.size()); }
  const FrequencyBand& operator[](int i) const { return bands_[static_cast<std::size_t>(i)]; }
  int fftSize() const { return fft_size_; }
  double sampleRate() const { return sample_rate_; }
  double binHz() const { return sample_rate_ / fft_size_; }
  // Index of the first band whose centre is at or above `hz` (size() if none).
  int firstBandFrom(double hz) const;

 private:
  void appendRange(double low_hz, double high_hz, double erb_step);

  int fft_size_ = 0;
  double sample_rate_ = 0;
  std::vector<FrequencyBand> bands_;
};

double erbNumber(double hz);
double hzOfErbNumber(double erb_number);

}  // namespace beft::hearing

#include "lib/hearing/band_signature.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lib/hearing/fft_convolver.hpp"

namespace beft::hearing {

BandSignature signatureOfSound(const std::vector<float>& samples, double sample_rate, const AnalysisLayout& layout) {
  if (!(sample_rate > 0)) throw std::invalid_argument("a sound's signature needs its sample rate > 0");
  for (float s : samples)
    if (!std::isfinite(s)) throw std::invalid_argument("a sound's signature needs finite samples");
  const FrequencyBands bands = layout.bands();
  BandSignature signature;
  signature.band_energy.assign(static_cast<std::size_t>(bands.size()), 0.0);
  if (samples.empty()) return signature;

  // Frames as long in time as the layout's, at the sound's own rate.
  const int frame = std::max(16, static_cast<int>(std::lround(layout.frame_size * sample_rate / layout.sample_rate)));
  const int hop = frame / 2;
  const RealFft fft(frame);
  std::vector<float> window(static_cast<std::size_t>(frame)), windowed(static_cast<std::size_t>(frame));
  for (int n = 0; n < frame; ++n)
    window[static_cast<std::size_t>(n)] = static_cast<float>(0.5 - 0.5 * std::cos(2 * M_PI * n / frame));
  // Which band each bin of this FFT falls in, by frequency (-1: none).
  const double bin_hz = sample_rate / frame;
  std::vector<int> band_of_bin(static_cast<std::size_t>(fft.bins()), -1);
  for (int k = 0; k < fft.bins(); ++k) {
    const double hz = k * bin_hz;
    for (int b = 0; b < bands.size(); ++b)
      if (hz >= bands[b].low_hz && hz < bands[b].high_hz) band_of_bin[static_cast<std::size_t>(k)] = b;
  }
  std::vector<std::complex<float>> spectrum;
  const long length = static_cast<long>(samples.size());
  for (long start = 0; start == 0 || start + frame <= length; start += hop) {
    for (int n = 0; n < frame; ++n) {
      const long i = start + n;
      windowed[static_cast<std::size_t>(n)] =
          i < length ? samples[static_cast<std::size_t>(i)] * window[static_cast<std::size_t>(n)] : 0.0f;
    }
    fft.forward(windowed, spectrum);
    for (int k = 0; k < fft.bins(); ++k)
      if (band_of_bin[static_cast<std::size_t>(k)] >= 0)
        signature.band_energy[static_cast<std::size_t>(band_of_bin[static_cast<std::size_t>(k)])] +=
            std::norm(spectrum[static_cast<std::size_t>(k)]);
  }
  return signature;
}

namespace {
// Band levels [dB], floored 50 dB below the loudest; empty if silent.
std::vector<double> flooredLevels(const BandSignature& s) {
  double loudest = 0;
  for (double e : s.band_energy) loudest = std::max(loudest, std::isfinite(e) ? e : 0.0);
  if (!(loudest > 0)) return {};
  std::vector<double> levels;
  const double floor = loudest * 1e-5;
  for (double e : s.band_energy) levels.push_back(10 * std::log10(std::max(std::isfinite(e) ? e : 0.0, floor)));
  return levels;
}
}  // namespace

double signatureSimilarity(const BandSignature& a, const BandSignature& b) {
  if (a.band_energy.size() != b.band_energy.size()) return 0;
  std::vector<double> x = flooredLevels(a), y = flooredLevels(b);
  if (x.empty() || y.empty()) return 0;
  const double n = static_cast<double>(x.size());
  double mean_x = 0, mean_y = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mean_x += x[i] / n, mean_y += y[i] / n;
  double xy = 0, xx = 0, yy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    xy += (x[i] - mean_x) * (y[i] - mean_y);
    xx += (x[i] - mean_x) * (x[i] - mean_x);
    yy += (y[i] - mean_y) * (y[i] - mean_y);
  }
  if (!(xx > 0) || !(yy > 0)) return xx == yy ? 1.0 : 0.0;  // two flat spectra are alike
  return xy / std::sqrt(xx * yy);
}

}  // namespace beft::hearing

#include "lib/hearing/interaural_templates.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lib/hearing/gcc_phat.hpp"
#include "lib/hearing/fft_convolver.hpp"

namespace beft::hearing {

InterauralTemplates::InterauralTemplates(const HorizontalHrirs& hrirs, const AnalysisLayout& layout)
    : layout_(layout), bands_(layout.bands()) {
  if (hrirs.left.size() != kAzimuths || hrirs.right.size() != kAzimuths)
    throw std::invalid_argument("interaural templates need responses for all 360 whole degrees of azimuth");
  if (std::abs(hrirs.sample_rate - layout.sample_rate) > 1e-6 * layout.sample_rate)
    throw std::invalid_argument("the responses are at " + std::to_string(hrirs.sample_rate) +
                                " Hz but the analysis at " + std::to_string(layout.sample_rate) + " Hz");
  first_level_band_ = bands_.firstBandFrom(layout.split_hz);
  phase_bins_ = first_level_band_ > 0 ? bands_[first_level_band_ - 1].end_bin : 0;
  if (layout.phase_high_hz > layout.split_hz)
    phase_bins_ = std::min(layout.frame_size / 2, static_cast<int>(std::lround(layout.phase_high_hz / bands_.binHz())));
  itd_s_.resize(kAzimuths);
  ild_db_.resize(static_cast<std::size_t>(kAzimuths) * static_cast<std::size_t>(bands_.size()));
  phase_.resize(static_cast<std::size_t>(kAzimuths) * static_cast<std::size_t>(phase_bins_));

  const RealFft fft(layout.frame_size);
  std::vector<std::complex<float>> spectrum_left, spectrum_right;
  for (int azimuth = 0; azimuth < kAzimuths; ++azimuth) {
    std::vector<float> left = hrirs.left[static_cast<std::size_t>(azimuth)];
    std::vector<float> right = hrirs.right[static_cast<std::size_t>(azimuth)];
    if (left.empty() || right.empty())
      throw std::invalid_argument("the response pair at azimuth " + std::to_string(azimuth) + " is empty");
    itd_s_[index(azimuth)] = gccPhatDelay(left, right, layout.sample_rate, layout.split_hz, 1.5e-3).delay_s;
    // Responses longer than a frame are cut: what follows is room and ringing, not the head.
    left.resize(static_cast<std::size_t>(layout.frame_size), 0.0f);
    right.resize(static_cast<std::size_t>(layout.frame_size), 0.0f);
    fft.forward(left, spectrum_left);
    fft.forward(right, spectrum_right);
    for (int b = 0; b < bands_.size(); ++b) {
      double energy_left = 0, energy_right = 0;
      for (int k = bands_[b].first_bin; k < bands_[b].end_bin; ++k) {
        energy_left += std::norm(spectrum_left[static_cast<std::size_t>(k)]);
        energy_right += std::norm(spectrum_right[static_cast<std::size_t>(k)]);
      }
      constexpr double kTiny = 1e-30;
      ild_db_[index(azimuth) * static_cast<std::size_t>(bands_.size()) + static_cast<std::size_t>(b)] =
          10 * std::log10((energy_left + kTiny) / (energy_right + kTiny));
    }
    for (int k = 0; k < phase_bins_; ++k) {
      const std::complex<float> cross =
          spectrum_left[static_cast<std::size_t>(k)] * std::conj(spectrum_right[static_cast<std::size_t>(k)]);
      const float magnitude = std::abs(cross);
      phase_[index(azimuth) * static_cast<std::size_t>(phase_bins_) + static_cast<std::size_t>(k)] =
          magnitude > 0 ? cross / magnitude : std::complex<float>(1, 0);
    }
  }
}

InterauralTemplates InterauralTemplates::fromSofa(const std::string& path, const AnalysisLayout& layout) {
  return InterauralTemplates(loadSofaHorizontal(path, layout.sample_rate), layout);
}

}  // namespace beft::hearing

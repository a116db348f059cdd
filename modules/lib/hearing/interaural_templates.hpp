// What a head's two ears should hear from each azimuth: the interaural time
// difference, the interaural phase of every low FFT bin and the interaural
// level difference of every band, computed from a set of head-related
// impulse responses for one analysis layout. Built from a different head
// (the MIT KEMAR) than the one that renders the ear signals, so localisation
// meets the mismatch a real listener would.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "lib/hearing/analysis_layout.hpp"
#include "lib/hearing/frequency_bands.hpp"
#include "lib/hearing/sofa_hrirs.hpp"

namespace beft::hearing {

class InterauralTemplates {
 public:
  static constexpr int kAzimuths = 360;

  // Throws std::invalid_argument if the responses are not 360 pairs at the layout's rate.
  InterauralTemplates(const HorizontalHrirs& hrirs, const AnalysisLayout& layout);
  // From a SOFA file (throws SofaError if it is missing or unusable).
  static InterauralTemplates fromSofa(const std::string& path = kMitKemarSofa,
                                      const AnalysisLayout& layout = AnalysisLayout{});

  const AnalysisLayout& layout() const { return layout_; }
  const FrequencyBands& bands() const { return bands_; }
  // Bands [0, firstLevelBand()) carry time cues, the rest level cues.
  int firstLevelBand() const { return first_level_band_; }
  // FFT bins [0, phaseBins()) have an interaural phase template.
  int phaseBins() const { return phase_bins_; }

  // [s], > 0 when the left ear hears first: the GCC-PHAT peak of the two
  // responses below the layout's split frequency.
  double itd(int azimuth_deg) const { return itd_s_[index(azimuth_deg)]; }
  // [dB], > 0 when the left ear is louder, per band of bands().
  double ild(int azimuth_deg, int band) const {
    return ild_db_[index(azimuth_deg) * static_cast<std::size_t>(bands_.size()) + static_cast<std::size_t>(band)];
  }
  // Unit phasor of the left response times the conjugate right one, per FFT bin below phaseBins().
  std::complex<float> interauralPhase(int azimuth_deg, int bin) const {
    return phase_[index(azimuth_deg) * static_cast<std::size_t>(phase_bins_) + static_cast<std::size_t>(bin)];
  }

 private:
  static std::size_t index(int azimuth_deg) { return static_cast<std::size_t>(((azimuth_deg % 360) + 360) % 360); }

  AnalysisLayout layout_;
  FrequencyBands bands_;
  int first_level_band_ = 0, phase_bins_ = 0;
  std::vector<double> itd_s_;                   // [azimuth]
  std::vector<double> ild_db_;                  // [azimuth][band]
  std::vector<std::complex<float>> phase_;      // [azimuth][bin]
};

}  // namespace beft::hearing

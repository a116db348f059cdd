#include "lib/hearing/block_localiser.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "lib/hearing/azimuth_votes.hpp"

namespace beft::hearing {

// One frame's spectra, reduced to what the votes need.
struct BlockLocaliser::FrameSpectra {
  std::vector<double> energy_left, energy_right;  // per band
  std::vector<std::complex<float>> cross;         // left times conjugate right, per bin with a phase template
  std::vector<float> level_db;                    // left over right power, per bin with a phase template [dB]
  std::vector<float> power_left, power_right;     // per bin with a phase template
  std::vector<float> coherence;                   // interaural coherence per bin with a phase template (1: none)
  std::vector<float> onset;                       // onset weight per bin with a phase template (1: none)
  std::vector<float> band_onset;                  // onset weight per band (1: none)
  long start = 0;                                 // first sample

  static FrameSpectra reduced(const std::vector<std::complex<float>>& spectrum_left,
                              const std::vector<std::complex<float>>& spectrum_right, const FrequencyBands& bands,
                              int phase_bins);
  // Band b's power per bin, both ears averaged.
  double density(const FrequencyBands& bands, int b) const {
    const auto i = static_cast<std::size_t>(b);
    return 0.5 * (energy_left[i] + energy_right[i]) / (bands[b].end_bin - bands[b].first_bin);
  }
};

LocaliserConfig LocaliserConfig::reverberant() {
  LocaliserConfig config;
  config.onset_exponent = 2;
  config.coherence_floor = 0.3;
  config.weight_exponent = 0;
  config.joint_blocks = true;
  return config;
}

namespace {

constexpr int kAzimuths = AzimuthPosterior::kBins;

// A vote heard `shift` degrees of head turn ago, in the frame of the head now:
// a source now at azimuth a was then at a + shift.
AzimuthVote rotated(AzimuthVote vote, int shift) {
  shift = ((shift % kAzimuths) + kAzimuths) % kAzimuths;
  if (shift == 0) return vote;
  std::array<float, kAzimuths> turned;
  for (int a = 0; a < kAzimuths; ++a)
    turned[static_cast<std::size_t>(a)] = vote.likelihood[static_cast<std::size_t>((a + shift) % kAzimuths)];
  vote.likelihood = turned;
  return vote;
}

void checkEarSignals(const std::vector<float>& left, const std::vector<float>& right) {
  if (left.size() != right.size())
    throw std::invalid_argument("the ear signals differ in length (" + std::to_string(left.size()) + " left, " +
                                std::to_string(right.size()) + " right samples)");
  for (std::size_t i = 0; i < left.size(); ++i)
    if (!std::isfinite(left[i]) || !std::isfinite(right[i]))
      throw std::invalid_argument("the ear signals hold a sample that is not finite (at " + std::to_string(i) + ")");
}

}  // namespace

BlockLocaliser::BlockLocaliser(InterauralTemplates templates, const LocaliserConfig& config)
    : templates_(std::move(templates)), config_(config), fft_(templates_.layout().frame_size) {
  if (!(config.silence_rms > 0) || !(config.band_range_db > 0) || !(config.phase_sharpness > 0) ||
      !(config.max_phase_sharpness > 0) || !(config.ild_spread_db > 0) || !(config.joint_ild_spread_db > 0) || !(config.level_cue_weight >= 0) ||
      !(config.min_peak_separation_deg >= 0) || !(config.min_peak_relative_weight >= 0) || config.max_peaks < 0)
    throw std::invalid_argument("the localiser's silence level, band range, sharpness and ILD spread must be > 0, "
                                "its weights, separation and peak count >= 0");
  const int size = templates_.layout().frame_size;
  window_.resize(static_cast<std::size_t>(size));
  for (int n = 0; n < size; ++n) {
    window_[static_cast<std::size_t>(n)] = static_cast<float>(0.5 - 0.5 * std::cos(2 * M_PI * n / size));
    window_power_ += static_cast<double>(window_[static_cast<std::size_t>(n)]) * window_[static_cast<std::size_t>(n)];
  }
}

// One frame's spectra reduced to band energies and, per bin with a phase
// template, the cross-spectrum and level difference.
BlockLocaliser::FrameSpectra BlockLocaliser::FrameSpectra::reduced(
    const std::vector<std::complex<float>>& spectrum_left, const std::vector<std::complex<float>>& spectrum_right,
    const FrequencyBands& bands, int phase_bins) {
  const int band_count = bands.size();
  FrameSpectra frame;
  frame.energy_left.assign(static_cast<std::size_t>(band_count), 0.0);
  frame.energy_right.assign(static_cast<std::size_t>(band_count), 0.0);
  for (int b = 0; b < band_count; ++b)
    for (int k = bands[b].first_bin; k < bands[b].end_bin; ++k) {
      frame.energy_left[static_cast<std::size_t>(b)] += std::norm(spectrum_left[static_cast<std::size_t>(k)]);
      frame.energy_right[static_cast<std::size_t>(b)] += std::norm(spectrum_right[static_cast<std::size_t>(k)]);
    }
  frame.cross.resize(static_cast<std::size_t>(phase_bins));
  frame.level_db.resize(static_cast<std::size_t>(phase_bins));
  frame.power_left.resize(static_cast<std::size_t>(phase_bins));
  frame.power_right.resize(static_cast<std::size_t>(phase_bins));
  frame.coherence.assign(static_cast<std::size_t>(phase_bins), 1.0f);
  frame.onset.assign(static_cast<std::size_t>(phase_bins), 1.0f);
  frame.band_onset.assign(static_cast<std::size_t>(band_count), 1.0f);
  for (int k = 0; k < phase_bins; ++k) {
    const auto i = static_cast<std::size_t>(k);
    frame.cross[i] = spectrum_left[i] * std::conj(spectrum_right[i]);
    frame.power_left[i] = std::norm(spectrum_left[i]);
    frame.power_right[i] = std::norm(spectrum_right[i]);
    frame.level_db[i] = static_cast<float>(
        10 * std::log10((std::norm(spectrum_left[i]) + 1e-30) / (std::norm(spectrum_right[i]) + 1e-30)));
  }
  return frame;
}

void BlockLocaliser::addVotes(const std::vector<float>& left, const std::vector<float>& right, int shift, AzimuthVotes& votes,
                              int& voting_frames) const {
  checkEarSignals(left, right);
  std::vector<FrameSpectra> frames = loudFrameSpectra(left, right);
  if (config_.coherence_floor > 0) interauralCoherence(frames);
  if (config_.onset_exponent > 0) onsetWeights(frames);
  voting_frames += static_cast<int>(frames.size());
  if (frames.empty()) return;

  const FrequencyBands& bands = templates_.bands();
  const double threshold = votingThreshold(frames);
  for (const FrameSpectra& f : frames) {
    for (int b = 0; b < bands.size(); ++b) {
      if (f.density(bands, b) < threshold) continue;
      if (bands[b].first_bin < templates_.phaseBins()) addPhaseVotes(f, b, shift, votes);
      if (b >= templates_.firstLevelBand() && config_.level_cue_weight > 0) addLevelVote(f, b, shift, votes);
    }
  }
}

// The spectra of the frames loud enough to vote.
std::vector<BlockLocaliser::FrameSpectra> BlockLocaliser::loudFrameSpectra(const std::vector<float>& left,
                                                                           const std::vector<float>& right) const {
  const int frame_size = templates_.layout().frame_size, hop = templates_.layout().hop;
  const long length = static_cast<long>(left.size());
  std::vector<FrameSpectra> frames;
  std::vector<float> windowed_left(static_cast<std::size_t>(frame_size)), windowed_right(windowed_left);
  std::vector<std::complex<float>> spectrum_left, spectrum_right;
  for (long start = 0; length > 0 && (start == 0 || start + frame_size <= length); start += hop) {
    double energy = 0;
    for (int n = 0; n < frame_size; ++n) {
      const long i = start + n;
      const float l = i < length ? left[static_cast<std::size_t>(i)] : 0.0f;
      const float r = i < length ? right[static_cast<std::size_t>(i)] : 0.0f;
      energy += static_cast<double>(l) * l + static_cast<double>(r) * r;
      windowed_left[static_cast<std::size_t>(n)] = l * window_[static_cast<std::size_t>(n)];
      windowed_right[static_cast<std::size_t>(n)] = r * window_[static_cast<std::size_t>(n)];
    }
    if (energy < 2.0 * frame_size * config_.silence_rms * config_.silence_rms) continue;
    fft_.forward(windowed_left, spectrum_left);
    fft_.forward(windowed_right, spectrum_right);
    frames.push_back(FrameSpectra::reduced(spectrum_left, spectrum_right, templates_.bands(), templates_.phaseBins()));
    frames.back().start = start;
  }
  return frames;
}

// Which bands vote: within band_range_db of the loudest, and above white
// noise at the silence level.
double BlockLocaliser::votingThreshold(const std::vector<FrameSpectra>& frames) const {
  const FrequencyBands& bands = templates_.bands();
  double loudest = 0;
  for (const FrameSpectra& f : frames)
    for (int b = 0; b < bands.size(); ++b) loudest = std::max(loudest, f.density(bands, b));
  return std::max(loudest * std::pow(10.0, -config_.band_range_db / 10),
                  config_.silence_rms * config_.silence_rms * window_power_);
}

// The onset weights (LocaliserConfig::onset_exponent) per frame, bin and band.
void BlockLocaliser::onsetWeights(std::vector<FrameSpectra>& frames) const {
  const int hop = templates_.layout().hop;
  const double decay = std::pow(10.0, -config_.onset_decay_db / 10);
  const auto weight = [&](double reference, double power) {
    if (!(power > 0)) return 0.0f;
    return static_cast<float>(std::pow(std::max(0.0, 1 - reference / power), config_.onset_exponent));
  };
  const std::size_t bins = frames.empty() ? 0 : frames.front().cross.size();
  const std::size_t bands = frames.empty() ? 0 : frames.front().energy_left.size();
  std::vector<double> reference(bins, 0.0), band_reference(bands, 0.0);
  for (std::size_t t = 0; t < frames.size(); ++t) {
    FrameSpectra& f = frames[t];
    const bool first = f.start == 0;
    const bool after_silence = t == 0 ? !first : f.start != frames[t - 1].start + hop;
    if (after_silence) {
      std::fill(reference.begin(), reference.end(), 0.0);
      std::fill(band_reference.begin(), band_reference.end(), 0.0);
    }
    for (std::size_t k = 0; k < bins; ++k) {
      const double power = 0.5 * (f.power_left[k] + f.power_right[k]);
      f.onset[k] = first ? static_cast<float>(config_.onset_first_frame_weight) : weight(reference[k], power);
      reference[k] = std::max(reference[k] * decay, power);
    }
    for (std::size_t b = 0; b < bands; ++b) {
      const double power = 0.5 * (f.energy_left[b] + f.energy_right[b]);
      f.band_onset[b] =
          first ? static_cast<float>(config_.onset_first_frame_weight) : weight(band_reference[b], power);
      band_reference[b] = std::max(band_reference[b] * decay, power);
    }
  }
}

// Faller and Merimaa's interaural coherence per frame and bin, the
// expectations taken over the loud frames before and after and the bins
// beside it (3 x 3).
void BlockLocaliser::interauralCoherence(std::vector<FrameSpectra>& frames) {
  const int count = static_cast<int>(frames.size());
  for (int t = 0; t < count; ++t) {
    auto& frame = frames[static_cast<std::size_t>(t)];
    const int bins = static_cast<int>(frame.cross.size());
    for (int k = 0; k < bins; ++k) {
      std::complex<double> cross = 0;
      double pl = 0, pr = 0;
      for (int u = std::max(0, t - 1); u <= std::min(count - 1, t + 1); ++u) {
        const auto& other = frames[static_cast<std::size_t>(u)];
        for (int j = std::max(0, k - 1); j <= std::min(bins - 1, k + 1); ++j) {
          const auto i = static_cast<std::size_t>(j);
          cross += std::complex<double>(other.cross[i]);
          pl += other.power_left[i];
          pr += other.power_right[i];
        }
      }
      const double norm = std::sqrt(pl * pr);
      frame.coherence[static_cast<std::size_t>(k)] = norm > 0 ? static_cast<float>(std::abs(cross) / norm) : 0.0f;
    }
  }
}

// Time cues: each bin on its own, so a tone or a harmonic holds its bin even
// where another sound holds the rest of the band. Its phase against each
// azimuth's template phase, as a von Mises likelihood whose concentration
// grows towards low frequencies, where the whole range of interaural delays
// spans only a fraction of a cycle (so each radian counts for more degrees).
void BlockLocaliser::addPhaseVotes(const FrameSpectra& f, int b, int shift, AzimuthVotes& votes) const {
  const FrequencyBands& bands = templates_.bands();
  const float joint_inverse_twice_variance =
      static_cast<float>(1.0 / (2 * config_.joint_ild_spread_db * config_.joint_ild_spread_db));
  for (int k = bands[b].first_bin; k < std::min(bands[b].end_bin, templates_.phaseBins()); ++k) {
    const std::complex<float> c = f.cross[static_cast<std::size_t>(k)];
    const float magnitude = std::abs(c);
    if (!(magnitude > 0)) continue;
    const double hz = std::max(k * bands.binHz(), 1.0);
    const float sharpness = static_cast<float>(
        std::min(config_.max_phase_sharpness, config_.phase_sharpness * config_.sharpness_reference_hz / hz));
    const bool joint = hz >= config_.joint_level_from_hz && hz < config_.joint_level_to_hz;
    const float heard_level = f.level_db[static_cast<std::size_t>(k)];
    AzimuthVote vote;
    for (int a = 0; a < kAzimuths; ++a) {
      const std::complex<float> t = templates_.interauralPhase(a, k);
      const float cosine = (c.real() * t.real() + c.imag() * t.imag()) / magnitude;
      float exponent = sharpness * (cosine - 1);
      if (joint) {
        const float difference = static_cast<float>(heard_level - templates_.ild(a, b));
        exponent -= difference * difference * joint_inverse_twice_variance;
      }
      vote.likelihood[static_cast<std::size_t>(a)] = std::exp(exponent);
    }
    vote.band = b;
    vote.energy = 2.0 * magnitude;  // |L| |R| per ear
    vote.weight = std::pow(vote.energy, config_.weight_exponent);
    if (config_.onset_exponent > 0) {
      vote.weight *= f.onset[static_cast<std::size_t>(k)];
      if (!(vote.weight > 0)) continue;
    }
    if (config_.coherence_floor > 0) {
      const double c = f.coherence[static_cast<std::size_t>(k)];
      const double selected = std::clamp((c - config_.coherence_floor) / (1 - config_.coherence_floor), 0.0, 1.0);
      vote.weight *= std::pow(selected, config_.coherence_exponent);
      if (!(vote.weight > 0)) continue;
    }
    votes.add(rotated(std::move(vote), shift));
  }
}

// Level cue: the band's ILD against each azimuth's template ILD.
void BlockLocaliser::addLevelVote(const FrameSpectra& f, int b, int shift, AzimuthVotes& votes) const {
  const float inverse_twice_variance = static_cast<float>(1.0 / (2 * config_.ild_spread_db * config_.ild_spread_db));
  const auto i = static_cast<std::size_t>(b);
  const double heard = 10 * std::log10((f.energy_left[i] + 1e-30) / (f.energy_right[i] + 1e-30));
  AzimuthVote vote;
  for (int a = 0; a < kAzimuths; ++a) {
    const float difference = static_cast<float>(heard - templates_.ild(a, b));
    vote.likelihood[static_cast<std::size_t>(a)] = std::exp(-difference * difference * inverse_twice_variance);
  }
  vote.band = b;
  vote.energy = f.energy_left[i] + f.energy_right[i];
  vote.weight = config_.level_cue_weight * std::pow(vote.energy, config_.weight_exponent);
  if (config_.onset_exponent > 0) vote.weight *= f.band_onset[i];
  votes.add(rotated(std::move(vote), shift));
}

BlockLocalisation BlockLocaliser::localise(const std::vector<float>& left, const std::vector<float>& right) const {
  return localise(std::vector<EarBlock>{EarBlock{left, right, 0.0}});
}

BlockLocalisation BlockLocaliser::localise(const std::vector<EarBlock>& blocks) const {
  AzimuthVotes votes(templates_.bands().size());
  BlockLocalisation result;
  for (const EarBlock& block : blocks) {
    votes.beginBlock();
    addVotes(block.left, block.right, static_cast<int>(std::lround(block.turned_since_deg)), votes, result.voting_frames);
  }
  if (result.voting_frames == 0) return result;
  result.posterior = votes.posterior();

  // 4. The sources, one after the other, with the band energy of the votes each explained.
  std::vector<FoundSource> sources = votes.separateSources(
      config_.max_peaks, config_.min_peak_separation_deg, config_.min_peak_relative_weight, config_.joint_blocks);
  for (FoundSource& source : sources) {
    LocalisedPeak peak;
    peak.azimuth_deg = source.azimuth_deg;
    peak.weight = source.weight;
    peak.signature.band_energy = std::move(source.band_energy);
    result.peaks.push_back(std::move(peak));
  }
  return result;
}

}  // namespace beft::hearing

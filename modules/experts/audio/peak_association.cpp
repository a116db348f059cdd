#include "experts/audio/peak_association.hpp"

#include <algorithm>
#include <tuple>

#include "lib/hearing/azimuth_posterior.hpp"

namespace beft::audio {
namespace {

using Pair = std::tuple<double, std::size_t, std::size_t>;  // (score, peak, object)

// The spectra's similarity, or a negative number when the object's sound
// cannot be told or does not match.
std::vector<std::vector<double>> similarities(const std::vector<hearing::LocalisedPeak>& peaks,
                                              const std::vector<SoundingObject>& sounding, double min_similarity) {
  std::vector<std::vector<double>> similarity(peaks.size(), std::vector<double>(sounding.size(), -1));
  for (std::size_t p = 0; p < peaks.size(); ++p) {
    for (std::size_t o = 0; o < sounding.size(); ++o) {
      if (sounding[o].signature == nullptr) continue;
      const double s = hearing::signatureSimilarity(peaks[p].signature, *sounding[o].signature);
      if (s >= min_similarity) similarity[p][o] = s;
    }
  }
  return similarity;
}

// Gives each pair's peak to its object, best score first: a peak to one
// object; an object a second peak only if it is the mirror image of its
// first. Marks the peaks taken; `first_peak`: each object's first peak.
void assign(std::vector<Pair> pairs, const std::vector<hearing::LocalisedPeak>& peaks, double mirror_deg,
            std::vector<bool>& taken, std::vector<ObjectPeaks>& out, std::vector<std::size_t>& first_peak) {
  std::stable_sort(pairs.begin(), pairs.end(),
                   [](const Pair& a, const Pair& b) { return std::get<0>(a) > std::get<0>(b); });
  for (const auto& [score, p, o] : pairs) {
    if (taken[p]) continue;
    const double azimuth = peaks[p].azimuth_deg;
    auto& own = out[o].azimuths_deg;
    const bool mirror_of_own = std::any_of(own.begin(), own.end(), [&](double first) {
      return hearing::angularDistance(hearing::frontBackMirror(first), azimuth) <= mirror_deg;
    });
    if (!own.empty() && !mirror_of_own) continue;
    if (own.empty()) first_peak[o] = p;
    own.push_back(azimuth);
    taken[p] = true;
  }
}

}  // namespace

std::vector<ObjectPeaks> associatePeaks(const std::vector<hearing::LocalisedPeak>& peaks, double head_yaw_deg,
                                        const std::vector<SoundingObject>& sounding,
                                        const std::vector<TrackPrediction>& predictions,
                                        const AssociationConfig& config) {
  std::vector<ObjectPeaks> out(sounding.size());
  const auto similarity = similarities(peaks, sounding, config.min_similarity);
  // How far the peak, or its front-back mirror image (interaural cues alike),
  // lies from the object's predicted bearing [deg].
  const auto offset = [&](std::size_t p, std::size_t o) {
    const double direct = hearing::wrapDegrees(head_yaw_deg + peaks[p].azimuth_deg);
    const double mirror = hearing::wrapDegrees(head_yaw_deg + hearing::frontBackMirror(peaks[p].azimuth_deg));
    double nearest = 180;
    for (const double expected : predictions[o].bearings_deg)
      nearest = std::min({nearest, hearing::angularDistance(direct, expected), hearing::angularDistance(mirror, expected)});
    return nearest;
  };
  const auto agreement = [&](std::size_t p, std::size_t o) { return 1 - offset(p, o) / config.gate_deg; };

  // Live objects take the peaks within their gates.
  std::vector<Pair> live_pairs;
  std::vector<bool> explained(peaks.size(), false);  // a live object of that sound could take it
  for (std::size_t p = 0; p < peaks.size(); ++p) {
    for (std::size_t o = 0; o < sounding.size(); ++o) {
      if (similarity[p][o] < 0 || !predictions[o].live || offset(p, o) > config.gate_deg) continue;
      live_pairs.emplace_back(similarity[p][o] + config.agreement_weight * agreement(p, o), p, o);
      explained[p] = true;
    }
  }
  std::vector<bool> taken(peaks.size(), false);
  std::vector<std::size_t> first_peak(sounding.size(), 0);
  assign(std::move(live_pairs), peaks, config.mirror_deg, taken, out, first_peak);

  // The peaks no live object explains start or resume another object: one
  // whose track predicts it, then one never heard, then one heard elsewhere.
  std::vector<Pair> other_pairs;
  for (std::size_t p = 0; p < peaks.size(); ++p) {
    if (taken[p] || explained[p]) continue;
    for (std::size_t o = 0; o < sounding.size(); ++o) {
      if (similarity[p][o] < 0 || predictions[o].live) continue;
      const bool resumes = predictions[o].heard && offset(p, o) <= config.gate_deg;
      const double preference = resumes ? 2 + agreement(p, o) : predictions[o].heard ? 0 : 1;
      other_pairs.emplace_back(similarity[p][o] + config.preference_weight * preference, p, o);
    }
  }
  std::vector<ObjectPeaks> others(sounding.size());
  assign(std::move(other_pairs), peaks, config.mirror_deg, taken, others, first_peak);
  for (std::size_t o = 0; o < sounding.size(); ++o) {
    if (others[o].azimuths_deg.empty()) continue;
    others[o].restart = predictions[o].heard && offset(first_peak[o], o) > config.gate_deg;
    out[o] = std::move(others[o]);
  }
  return out;
}

}  // namespace beft::audio

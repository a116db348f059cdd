#include "lib/hearing/azimuth_posterior.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace beft::hearing {

namespace {
constexpr int kBins = AzimuthPosterior::kBins;

int wrapIndex(int i) { return ((i % kBins) + kBins) % kBins; }
}  // namespace

double wrapDegrees(double degrees) {
  double wrapped = std::fmod(degrees, 360.0);
  if (wrapped < 0) wrapped += 360.0;
  return wrapped >= 360.0 ? 0.0 : wrapped;
}

double angularDistance(double a_deg, double b_deg) {
  const double d = wrapDegrees(a_deg - b_deg);
  return std::min(d, 360.0 - d);
}

double frontBackMirror(double azimuth_deg) { return wrapDegrees(180.0 - azimuth_deg); }

AzimuthPosterior::AzimuthPosterior() { p_.fill(1.0 / kBins); }

AzimuthPosterior::AzimuthPosterior(const std::array<double, kBins>& values) {
  double sum = 0;
  for (double v : values) {
    if (!std::isfinite(v) || v < 0)
      throw std::invalid_argument("an azimuth posterior needs finite values >= 0");
    sum += v;
  }
  if (!(sum > 0) || !std::isfinite(sum)) {
    p_.fill(1.0 / kBins);
    return;
  }
  for (int i = 0; i < kBins; ++i) p_[static_cast<std::size_t>(i)] = values[static_cast<std::size_t>(i)] / sum;
}

double AzimuthPosterior::at(double azimuth_deg) const {
  const double a = wrapDegrees(azimuth_deg);
  const int below = static_cast<int>(std::floor(a));
  const double t = a - below;
  return (1 - t) * (*this)[wrapIndex(below)] + t * (*this)[wrapIndex(below + 1)];
}

bool AzimuthPosterior::isFlat() const {
  const auto [low, high] = std::minmax_element(p_.begin(), p_.end());
  return *high - *low <= 1e-9 * *high;
}

std::vector<AzimuthPeak> AzimuthPosterior::peaks(double min_separation_deg, double min_relative_weight) const {
  std::vector<AzimuthPeak> candidates, result;
  if (isFlat()) return result;
  for (int i = 0; i < kBins; ++i) {
    const double before = (*this)[wrapIndex(i - 1)], here = (*this)[i], after = (*this)[wrapIndex(i + 1)];
    // A plateau counts once, at its first bin.
    if (!(here > before && here >= after)) continue;
    // Refined by the parabola through the bin and its neighbours.
    const double curvature = before - 2 * here + after;
    const double offset = curvature < 0 ? std::clamp(0.5 * (before - after) / curvature, -0.5, 0.5) : 0.0;
    const double azimuth = wrapDegrees(i + offset);
    candidates.push_back({azimuth, massNear(azimuth, 0.5 * min_separation_deg)});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const AzimuthPeak& a, const AzimuthPeak& b) { return a.weight > b.weight; });
  for (const AzimuthPeak& candidate : candidates) {
    if (candidate.weight < min_relative_weight * candidates.front().weight) break;
    const bool separate = std::all_of(result.begin(), result.end(), [&](const AzimuthPeak& kept) {
      return angularDistance(kept.azimuth_deg, candidate.azimuth_deg) >= min_separation_deg;
    });
    if (separate) result.push_back(candidate);
  }
  return result;
}

double AzimuthPosterior::mostLikely() const {
  if (isFlat()) return 0;
  const int i = static_cast<int>(std::max_element(p_.begin(), p_.end()) - p_.begin());
  const double before = (*this)[wrapIndex(i - 1)], here = (*this)[i], after = (*this)[wrapIndex(i + 1)];
  const double curvature = before - 2 * here + after;
  const double offset = curvature < 0 ? std::clamp(0.5 * (before - after) / curvature, -0.5, 0.5) : 0.0;
  return wrapDegrees(i + offset);
}

double AzimuthPosterior::massNear(double azimuth_deg, double half_width_deg) const {
  const int centre = static_cast<int>(std::lround(azimuth_deg));
  const int half = std::min(kBins / 2, static_cast<int>(std::lround(half_width_deg)));
  double sum = 0;
  for (int i = centre - half; i <= centre + half && i < centre - half + kBins; ++i) sum += (*this)[wrapIndex(i)];
  return sum;
}

AzimuthPosterior AzimuthPosterior::inTurnedFrame(double turn_deg) const {
  std::array<double, kBins> turned{};
  for (int i = 0; i < kBins; ++i) turned[static_cast<std::size_t>(i)] = at(i + turn_deg);
  return AzimuthPosterior(turned);
}

bool isFrontBackAmbiguous(const AzimuthPosterior& posterior, double min_ratio, double half_width_deg) {
  if (posterior.isFlat()) return false;
  const double direction = posterior.mostLikely();
  const double mirror = frontBackMirror(direction);
  if (angularDistance(direction, mirror) <= 2 * half_width_deg) return false;
  return posterior.massNear(mirror, half_width_deg) >= min_ratio * posterior.massNear(direction, half_width_deg);
}

}  // namespace beft::hearing

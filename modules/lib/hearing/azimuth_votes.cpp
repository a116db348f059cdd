#include "lib/hearing/azimuth_votes.hpp"

#include <algorithm>
#include <cmath>

namespace beft::hearing {

namespace {
constexpr int kBins = AzimuthPosterior::kBins;
// Added to each block's residual, normalised to sum 1, as this share of the
// flat value before the geometric mean: a direction one block gives nothing
// is weakened, not vetoed (a source may fall quiet in one block).
constexpr double kJointFloor = 0.05;

std::array<double, kBins> weightedSum(const std::vector<AzimuthVote>& votes, const std::vector<double>& weights) {
  std::array<double, kBins> sum{};
  for (std::size_t v = 0; v < votes.size(); ++v) {
    if (!(weights[v] > 0)) continue;
    for (int a = 0; a < kBins; ++a)
      sum[static_cast<std::size_t>(a)] += weights[v] * votes[v].likelihood[static_cast<std::size_t>(a)];
  }
  return sum;
}
}  // namespace

// The geometric mean over the blocks of each block's residual, normalised.
std::array<double, kBins> AzimuthVotes::jointResidual(const std::vector<double>& weights) const {
  std::array<double, kBins> joint;
  joint.fill(0.0);
  const int count = blocks();
  for (int b = 0; b < count; ++b) {
    std::array<double, kBins> sum{};
    double total = 0;
    for (std::size_t v = 0; v < votes_.size(); ++v) {
      if (votes_[v].block != b || !(weights[v] > 0)) continue;
      total += weights[v];
      for (int a = 0; a < kBins; ++a)
        sum[static_cast<std::size_t>(a)] += weights[v] * votes_[v].likelihood[static_cast<std::size_t>(a)];
    }
    // A block with nothing left says nothing (flat); a floor keeps one empty direction from vetoing all.
    for (int a = 0; a < kBins; ++a) {
      const double p = total > 0 ? sum[static_cast<std::size_t>(a)] / total : 1.0 / kBins;
      joint[static_cast<std::size_t>(a)] += std::log(p + kJointFloor / kBins) / count;
    }
  }
  for (double& j : joint) j = std::exp(j);
  return joint;
}

void AzimuthVotes::add(AzimuthVote vote) {
  double total = 0;
  for (float l : vote.likelihood) total += l;
  if (!(total > 0) || !std::isfinite(total) || !(vote.weight > 0) || !std::isfinite(vote.weight)) return;
  for (float& l : vote.likelihood) l = static_cast<float>(l / total);
  vote.block = block_;
  votes_.push_back(std::move(vote));
}

AzimuthPosterior AzimuthVotes::posterior() const {
  std::vector<double> weights(votes_.size());
  for (std::size_t v = 0; v < votes_.size(); ++v) weights[v] = votes_[v].weight;
  return AzimuthPosterior(weightedSum(votes_, weights));
}

std::vector<FoundSource> AzimuthVotes::separateSources(int max_sources, double min_separation_deg,
                                                       double min_relative_weight, bool jointly) const {
  std::vector<FoundSource> found;
  std::vector<double> weights(votes_.size());
  double total_weight = 0;
  std::vector<float> highest(votes_.size());
  for (std::size_t v = 0; v < votes_.size(); ++v) {
    weights[v] = votes_[v].weight;
    total_weight += weights[v];
    highest[v] = *std::max_element(votes_[v].likelihood.begin(), votes_[v].likelihood.end());
  }
  if (!(total_weight > 0)) return found;

  while (static_cast<int>(found.size()) < max_sources) {
    const AzimuthPosterior residual(jointly && blocks() > 1 ? jointResidual(weights) : weightedSum(votes_, weights));
    if (residual.isFlat()) break;
    // The heaviest peak of what is left that is not one already found.
    const auto candidates = residual.peaks(min_separation_deg, 0);
    const AzimuthPeak* next = nullptr;
    for (const AzimuthPeak& candidate : candidates) {
      const bool separate = std::all_of(found.begin(), found.end(), [&](const FoundSource& s) {
        return angularDistance(s.azimuth_deg, candidate.azimuth_deg) >= min_separation_deg;
      });
      if (separate) {
        next = &candidate;
        break;
      }
    }
    if (next == nullptr) break;

    FoundSource source;
    source.azimuth_deg = next->azimuth_deg;
    source.band_energy.assign(static_cast<std::size_t>(band_count_), 0.0);
    const auto at = static_cast<std::size_t>(static_cast<int>(std::lround(source.azimuth_deg)) % kBins);
    double explained = 0;
    for (std::size_t v = 0; v < votes_.size(); ++v) {
      if (!(weights[v] > 0)) continue;
      const double share = std::clamp(static_cast<double>(votes_[v].likelihood[at]) / highest[v], 0.0, 1.0);
      const double taken = weights[v] * share;
      weights[v] -= taken;
      explained += taken;
      const auto band = static_cast<std::size_t>(votes_[v].band);
      if (band < source.band_energy.size()) source.band_energy[band] += votes_[v].energy * taken / votes_[v].weight;
    }
    source.weight = explained / total_weight;
    if (!found.empty() && source.weight < min_relative_weight * found.front().weight) break;
    found.push_back(std::move(source));
  }
  return found;
}

}  // namespace beft::hearing

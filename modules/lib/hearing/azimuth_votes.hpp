// The votes of a block's time-frequency bins over azimuth, and how several
// sources are told apart in them. Each vote is a distribution over azimuth
// with a weight; their weighted sum is the posterior. Sources are taken out
// one at a time: the heaviest peak of what is left, then every vote loses
// the share of its weight that this direction explains (its value there over
// its own maximum), so the next source shows even where it was hidden under
// the first one's shoulders or its front-back mirror image (which explains
// the same votes and goes with it).
#pragma once

#include <array>
#include <vector>

#include "lib/hearing/azimuth_posterior.hpp"

namespace beft::hearing {

struct AzimuthVote {
  std::array<float, AzimuthPosterior::kBins> likelihood;  // sums to 1
  double weight = 0;  // > 0
  int band = 0;       // the band the vote came from
  int block = 0;      // the block it came from (AzimuthVotes::beginBlock)
  double energy = 0;  // of the bin or band, both ears
};

struct FoundSource {
  double azimuth_deg = 0;
  double weight = 0;                // share of all the votes' weight it explained
  std::vector<double> band_energy;  // energy of the votes it explained, per band
};

class AzimuthVotes {
 public:
  explicit AzimuthVotes(int band_count) : band_count_(band_count) {}

  // Scales the likelihood to sum 1; a vote that is all zero or has no weight is dropped.
  void add(AzimuthVote vote);
  // The votes added from now on come from the next block (heard with the
  // head turned otherwise); the first block needs no call.
  void beginBlock() { if (!votes_.empty()) ++block_; }
  int blocks() const { return block_ + 1; }
  bool empty() const { return votes_.empty(); }
  std::size_t size() const { return votes_.size(); }

  // The weighted sum of the votes, normalised (flat if there are none).
  AzimuthPosterior posterior() const;
  // Up to max_sources directions, strongest first, each explaining at least
  // min_relative_weight of what the first did and min_separation_deg from
  // every earlier one.
  //
  // With votes of several blocks and `jointly`, a direction is weighed by
  // the geometric mean over the blocks of what each block's own votes (each
  // block's residual normalised to sum 1) give it, rather than by their
  // sum: a source is heard in every block at the direction it has in the
  // frame of the head now, while its front-back mirror image moves by twice
  // each turn, so the mirror images are supported by one block each and the
  // true direction by all. Summed, two blocks' mirror images (each of them
  // often as heavy as the true direction within its block, since the two
  // heads' pinnae differ) or one block's mirror image and another talker's
  // votes can outweigh it.
  std::vector<FoundSource> separateSources(int max_sources, double min_separation_deg,
                                           double min_relative_weight, bool jointly = false) const;

 private:
  std::array<double, AzimuthPosterior::kBins> jointResidual(const std::vector<double>& weights) const;

  int band_count_;
  int block_ = 0;
  std::vector<AzimuthVote> votes_;
};

}  // namespace beft::hearing

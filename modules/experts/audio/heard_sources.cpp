#include "experts/audio/heard_sources.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace beft::audio {
namespace {

using hearing::AzimuthPosterior;

// The part of a head-frame posterior within half_width of the given peaks.
std::optional<AzimuthPosterior> partNear(const AzimuthPosterior& posterior, const std::vector<double>& peaks_deg,
                                         double half_width_deg) {
  std::array<double, AzimuthPosterior::kBins> values{};
  double sum = 0;
  for (int a = 0; a < AzimuthPosterior::kBins; ++a) {
    const bool near = std::any_of(peaks_deg.begin(), peaks_deg.end(),
                                  [&](double p) { return hearing::angularDistance(a, p) <= half_width_deg; });
    if (near) sum += values[static_cast<std::size_t>(a)] = posterior[a];
  }
  if (!(sum > 0)) return std::nullopt;
  return AzimuthPosterior(values);
}

// Evidence in the log domain, old evidence fading: log W <- (1 - forgetting)
// log W + log(1 + evidence * heard / max(heard)). One block can at most
// multiply a direction's odds by 1 + evidence, so a stray peak (a tonal
// sound's phase ambiguity, two sources mixed in one bin) moves nothing; what
// is heard block after block takes over within a second; and as the robot
// moves, the directions it heard the source in before fade instead of
// smearing the posterior along its way.
void accumulate(std::array<double, AzimuthPosterior::kBins>& log_evidence, const AzimuthPosterior& heard,
                double forgetting, double evidence) {
  double top = 0;
  for (int a = 0; a < AzimuthPosterior::kBins; ++a) top = std::max(top, heard[a]);
  if (!(top > 0)) return;
  for (int a = 0; a < AzimuthPosterior::kBins; ++a) {
    auto& value = log_evidence[static_cast<std::size_t>(a)];
    value = (1 - forgetting) * value + std::log1p(evidence * heard[a] / top);
  }
}

AzimuthPosterior posteriorOf(const std::array<double, AzimuthPosterior::kBins>& log_evidence) {
  const double top = *std::max_element(log_evidence.begin(), log_evidence.end());
  std::array<double, AzimuthPosterior::kBins> values{};
  for (std::size_t a = 0; a < values.size(); ++a) values[a] = std::exp(log_evidence[a] - top);
  return AzimuthPosterior(values);
}

// A second direction of a track's posterior this large, relative to the
// first, is where the source may be too (its front-back mirror image).
constexpr double kSecondBearingShare = 0.3;

Eigen::Vector2d unitOf(double bearing_deg) {
  const double radians = bearing_deg * M_PI / 180.0;
  return {std::cos(radians), std::sin(radians)};
}

}  // namespace

void HeardSources::hear(const hearing::BlockLocalisation& heard, const binaural_block_t& block,
                        const std::vector<SoundingObject>& sounding) {
  last_tick_ = block.tick;
  last_head_yaw_ = block.head_yaw;
  if (heard.silent() || heard.peaks.empty()) return;

  const auto peaks_of = associatePeaks(heard.peaks, block.head_yaw, sounding, predictions(sounding, block),
                                       config_.association);
  for (std::size_t o = 0; o < sounding.size(); ++o) {
    if (peaks_of[o].azimuths_deg.empty()) continue;
    const auto part = partNear(heard.posterior, peaks_of[o].azimuths_deg, config_.peak_half_width_deg);
    if (!part) continue;
    Track& track = tracks_[sounding[o].id];
    if (peaks_of[o].restart) {
      // Another source of the same sound: what was heard of the last one goes.
      track.log_evidence.fill(0);
      track.lines.clear();
      track.crossing.reset();
    }
    confirm(track, block.tick);
    update(track, part->inTurnedFrame(-block.head_yaw), block);
  }
}

// Where each object's track expects it now: towards the crossing of its
// bearings once they cross, else the directions of its posterior.
std::vector<TrackPrediction> HeardSources::predictions(const std::vector<SoundingObject>& sounding,
                                                       const binaural_block_t& block) const {
  std::vector<TrackPrediction> out(sounding.size());
  for (std::size_t o = 0; o < sounding.size(); ++o) {
    const auto found = tracks_.find(sounding[o].id);
    if (found == tracks_.end() || found->second.world.isFlat()) continue;
    const Track& track = found->second;
    out[o].heard = true;
    out[o].live = block.utime - track.last_heard_utime <= config_.live_s * 1e6;
    if (track.crossing) {
      const Eigen::Vector2d towards = *track.crossing - Eigen::Vector2d(block.head_x, block.head_y);
      out[o].bearings_deg = {std::atan2(towards.y(), towards.x()) * 180.0 / M_PI};
      continue;
    }
    for (const auto& peak : track.world.peaks(2 * config_.peak_half_width_deg, kSecondBearingShare))
      out[o].bearings_deg.push_back(peak.azimuth_deg);
    if (out[o].bearings_deg.empty()) out[o].bearings_deg = {track.world.mostLikely()};
  }
  return out;
}

// M of N: confirmed once given a peak in confirm_blocks of the last
// confirm_window_blocks blocks.
void HeardSources::confirm(Track& track, int64_t tick) const {
  auto& recent = track.recent_ticks;
  recent.push_back(tick);
  if (static_cast<int>(recent.size()) > config_.confirm_blocks) recent.erase(recent.begin());
  if (static_cast<int>(recent.size()) == config_.confirm_blocks &&
      tick - recent.front() < config_.confirm_window_blocks)
    track.confirmed = true;
}

void HeardSources::update(Track& track, const hearing::AzimuthPosterior& heard_world, const binaural_block_t& block) {
  accumulate(track.log_evidence, heard_world, config_.forgetting, config_.evidence_per_block);
  track.world = posteriorOf(track.log_evidence);
  track.heard_from = {block.head_x, block.head_y};
  track.last_heard_tick = block.tick;
  track.last_heard_utime = block.utime;

  auto& lines = track.lines;
  const std::size_t lines_before = lines.size();
  lines.erase(std::remove_if(lines.begin(), lines.end(),
                             [&](const auto& line) { return block.utime - line.first > config_.line_max_age_s * 1e6; }),
              lines.end());
  bool changed = lines.size() != lines_before;
  const AzimuthPosterior in_head = track.world.inTurnedFrame(block.head_yaw);
  const double bearing = track.world.mostLikely();
  const bool clear = track.world.massNear(bearing, 10) >= config_.clear_mass && !hearing::isFrontBackAmbiguous(in_head);
  const bool moved = lines.empty() || (lines.back().second.from - track.heard_from).norm() >= config_.line_spacing_m;
  if (clear && moved) {
    lines.emplace_back(block.utime, BearingLine{track.heard_from, bearing});
    if (static_cast<int>(lines.size()) > config_.max_lines) lines.erase(lines.begin());
    changed = true;
  }
  if (!changed) return;
  std::vector<BearingLine> bearings;
  for (const auto& [utime, line] : lines) bearings.push_back(line);
  track.crossing = triangulateRobustly(bearings, config_.triangulation);
}

std::optional<HeardEstimate> HeardSources::estimate(const std::string& id) const {
  const auto found = tracks_.find(id);
  if (found == tracks_.end() || found->second.world.isFlat() || !found->second.confirmed) return std::nullopt;
  const Track& track = found->second;
  HeardEstimate estimate;
  estimate.bearing_deg = track.world.mostLikely();
  if (track.crossing) {
    estimate.position = *track.crossing;
    estimate.triangulated = true;
  } else {
    estimate.position = track.heard_from + config_.default_distance_m * unitOf(estimate.bearing_deg);
  }
  return estimate;
}

std::optional<double> HeardSources::wantsHeadTurn(double head_yaw_deg, double limit_deg, int64_t utime,
                                                  std::string* object_id) {
  if (last_turn_utime_ >= 0 && utime - last_turn_utime_ < config_.turn_interval_s * 1e6) return std::nullopt;
  for (const auto& [id, track] : tracks_) {
    if (track.last_heard_tick != last_tick_) continue;
    if (!hearing::isFrontBackAmbiguous(track.world.inTurnedFrame(last_head_yaw_))) continue;
    last_turn_utime_ = utime;
    if (object_id != nullptr) *object_id = id;
    const double left = head_yaw_deg + config_.turn_deg;
    return left <= limit_deg ? left : head_yaw_deg - config_.turn_deg;
  }
  return std::nullopt;
}

}  // namespace beft::audio

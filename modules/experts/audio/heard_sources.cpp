#include "experts/audio/heard_sources.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <vector>

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

Eigen::Vector2d unitOf(double bearing_deg) {
  const double radians = bearing_deg * M_PI / 180.0;
  return {std::cos(radians), std::sin(radians)};
}

// Which peaks come from the direction where each seen object was seen, or
// from its front-back mirror image, within within_deg; and which sounds were
// seen in each peak's direction.
struct SeenDirections {
  std::vector<std::vector<bool>> there;                            // [peak][object]
  std::vector<std::set<const hearing::BandSignature*>> explained;  // [peak]
};

SeenDirections seenDirections(const hearing::BlockLocalisation& heard, const binaural_block_t& block,
                              const std::vector<SoundingObject>& sounding, double within_deg) {
  SeenDirections seen;
  seen.there.assign(heard.peaks.size(), std::vector<bool>(sounding.size(), false));
  seen.explained.resize(heard.peaks.size());
  const Eigen::Vector2d head(block.head_x, block.head_y);
  for (std::size_t o = 0; o < sounding.size() && within_deg > 0; ++o) {
    if (!sounding[o].seen_at || sounding[o].signature == nullptr) continue;
    const Eigen::Vector2d to = *sounding[o].seen_at - head;
    const double bearing = std::atan2(to.y(), to.x()) * 180.0 / M_PI;
    for (std::size_t p = 0; p < heard.peaks.size(); ++p) {
      const double azimuth = heard.peaks[p].azimuth_deg;
      const auto near = [&](double head_deg) {
        return hearing::angularDistance(hearing::wrapDegrees(block.head_yaw + head_deg), bearing) <= within_deg;
      };
      if (to.norm() < 1e-6 || near(azimuth) || near(hearing::frontBackMirror(azimuth))) {
        seen.there[p][o] = true;
        seen.explained[p].insert(sounding[o].signature);
      }
    }
  }
  return seen;
}

}  // namespace

void HeardSources::hear(const hearing::BlockLocalisation& heard, const binaural_block_t& block,
                        const std::vector<SoundingObject>& sounding) {
  last_tick_ = block.tick;
  last_head_yaw_ = block.head_yaw;
  if (heard.silent() || heard.peaks.empty()) return;

  // How alike each peak's spectrum is to each object's sound (0: not comparable).
  std::vector<std::vector<double>> similarity(heard.peaks.size(), std::vector<double>(sounding.size(), 0.0));
  for (std::size_t p = 0; p < heard.peaks.size(); ++p)
    for (std::size_t o = 0; o < sounding.size(); ++o)
      if (sounding[o].signature != nullptr)
        similarity[p][o] = hearing::signatureSimilarity(heard.peaks[p].signature, *sounding[o].signature);
  // Objects of one sound (one signature) cannot be told apart by their
  // spectra: among them, a peak from where one of them was seen (or from
  // its front-back mirror image) is that one's.
  std::map<const hearing::BandSignature*, int> objects_of_sound;
  for (const auto& object : sounding)
    if (object.signature != nullptr) ++objects_of_sound[object.signature];
  const SeenDirections seen = seenDirections(heard, block, sounding, config_.seen_explains_deg);
  // A seen object takes only peaks from where it was seen (a validation
  // gate): once the robot has moved far from it, a louder or nearer source
  // of a like spectrum would otherwise pull its estimate towards the robot.
  const auto placedByDirection = [&](std::size_t p, std::size_t o) {  // true: may take the peak
    if (!(config_.seen_explains_deg > 0)) return true;
    if (sounding[o].seen_at) return static_cast<bool>(seen.there[p][o]);
    return objects_of_sound[sounding[o].signature] < 2 || seen.explained[p].count(sounding[o].signature) == 0;
  };

  // Every (peak, object) pair whose spectra match, best first.
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;  // (score, peak, object)
  for (std::size_t p = 0; p < heard.peaks.size(); ++p) {
    const double world_deg = hearing::wrapDegrees(block.head_yaw + heard.peaks[p].azimuth_deg);
    for (std::size_t o = 0; o < sounding.size(); ++o) {
      if (similarity[p][o] < config_.min_similarity || !placedByDirection(p, o)) continue;
      double agreement = 0;  // heard from there before: how likely that direction was
      if (const auto track = tracks_.find(sounding[o].id); track != tracks_.end() && !track->second.world.isFlat()) {
        const double top = track->second.world.at(track->second.world.mostLikely());
        agreement = top > 0 ? track->second.world.at(world_deg) / top : 0;
      }
      pairs.emplace_back(similarity[p][o] + 0.2 * agreement, p, o);
    }
  }
  std::stable_sort(pairs.begin(), pairs.end(),
                   [](const auto& a, const auto& b) { return std::get<0>(a) > std::get<0>(b); });
  // Each peak to one object; an object takes a second peak only if it is the
  // front-back mirror image of its first (the same source heard both ways).
  std::vector<std::vector<double>> peaks_of(sounding.size());
  std::vector<bool> taken(heard.peaks.size(), false);
  for (const auto& [score, p, o] : pairs) {
    if (taken[p]) continue;
    const double azimuth = heard.peaks[p].azimuth_deg;
    const bool mirror_of_own = std::any_of(peaks_of[o].begin(), peaks_of[o].end(), [&](double own) {
      return hearing::angularDistance(hearing::frontBackMirror(own), azimuth) <= 2 * config_.peak_half_width_deg;
    });
    if (!peaks_of[o].empty() && !mirror_of_own) continue;
    peaks_of[o].push_back(azimuth);
    taken[p] = true;
  }
  for (std::size_t o = 0; o < sounding.size(); ++o) {
    if (peaks_of[o].empty()) continue;
    const auto part = partNear(heard.posterior, peaks_of[o], config_.peak_half_width_deg);
    if (!part) continue;
    update(tracks_[sounding[o].id], part->inTurnedFrame(-block.head_yaw), block);
  }
}

void HeardSources::update(Track& track, const hearing::AzimuthPosterior& heard_world, const binaural_block_t& block) {
  accumulate(track.log_evidence, heard_world, config_.forgetting, config_.evidence_per_block);
  track.world = posteriorOf(track.log_evidence);
  track.heard_from = {block.head_x, block.head_y};
  track.last_heard_tick = block.tick;

  auto& lines = track.lines;
  lines.erase(std::remove_if(lines.begin(), lines.end(),
                             [&](const auto& line) { return block.utime - line.first > config_.line_max_age_s * 1e6; }),
              lines.end());
  const AzimuthPosterior in_head = track.world.inTurnedFrame(block.head_yaw);
  const double bearing = track.world.mostLikely();
  const bool clear = track.world.massNear(bearing, 10) >= config_.clear_mass && !hearing::isFrontBackAmbiguous(in_head);
  const bool moved = lines.empty() || (lines.back().second.from - track.heard_from).norm() >= config_.line_spacing_m;
  if (clear && moved) {
    lines.emplace_back(block.utime, BearingLine{track.heard_from, bearing});
    if (static_cast<int>(lines.size()) > config_.max_lines) lines.erase(lines.begin());
  }
  keepFix(track, clear, block.utime);
}

void HeardSources::keepFix(Track& track, bool clear, int64_t utime) const {
  if (!(config_.fix_agreement_deg > 0)) track.fix.reset();
  // A fix the clear direction has missed for fix_disagreement_s is dropped,
  // with the lines heard before the miss began that made it: the source
  // moved, or they were another source's. A moment's miss (a mirror image,
  // a peak of another source) is not enough.
  if (!fixAgrees(track, clear)) {
    if (track.disagreeing_since < 0) track.disagreeing_since = utime;
    if (static_cast<double>(utime - track.disagreeing_since) * 1e-6 >= config_.fix_disagreement_s) {
      track.fix.reset();
      const int64_t since = track.disagreeing_since;
      track.lines.erase(std::remove_if(track.lines.begin(), track.lines.end(),
                                       [&](const auto& line) { return line.first < since; }),
                        track.lines.end());
    }
  } else if (clear) {
    track.disagreeing_since = -1;
  }
  if (!track.fix) track.disagreeing_since = -1;
  std::vector<BearingLine> lines;
  for (const auto& [line_utime, line] : track.lines) lines.push_back(line);
  if (const auto crossing = triangulate(lines, config_.triangulation)) {
    // The lines' error where the kept fix is, if there is one: the lines
    // themselves may cross nearer than the source, and by their distance
    // to that crossing they would look more certain than they are.
    const double error = crossingError(lines, track.fix ? *track.fix : *crossing, config_.bearing_sd_deg,
                                       config_.triangulation);
    const double kept_error =
        track.fix ? track.fix_error_m + config_.fix_aging_mps * static_cast<double>(utime - track.fix_utime) * 1e-6
                  : std::numeric_limits<double>::infinity();
    if (!track.fix || !(kept_error < error)) {
      track.fix = *crossing;
      track.fix_error_m = error;
      track.fix_utime = utime;
      track.disagreeing_since = -1;
    }
  }
}

// Whether the fix is still where the source is heard: always while the
// direction is unclear or the robot is near the fix.
bool HeardSources::fixAgrees(const Track& track, bool clear) const {
  if (!track.fix || !clear) return true;
  const Eigen::Vector2d to_fix = *track.fix - track.heard_from;
  if (to_fix.norm() < config_.fix_near_m) return true;
  const double fix_bearing = std::atan2(to_fix.y(), to_fix.x()) * 180.0 / M_PI;
  return hearing::angularDistance(fix_bearing, track.world.mostLikely()) <= config_.fix_agreement_deg;
}

std::optional<HeardEstimate> HeardSources::estimate(const std::string& id) const {
  const auto found = tracks_.find(id);
  if (found == tracks_.end() || found->second.world.isFlat()) return std::nullopt;
  const Track& track = found->second;
  HeardEstimate estimate;
  estimate.bearing_deg = track.world.mostLikely();
  if (track.fix) {
    estimate.position = *track.fix;
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

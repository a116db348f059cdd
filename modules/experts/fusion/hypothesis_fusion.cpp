#include "experts/fusion/hypothesis_fusion.hpp"

#include <algorithm>
#include <array>
#include <set>
#include <stdexcept>
#include <unordered_map>

namespace beft::fusion {

namespace {

// Index of the highest confidence (the first one on ties), or -1 if empty.
int bestIndex(const std::vector<double>& confidence) {
  if (confidence.empty()) return -1;
  return static_cast<int>(std::max_element(confidence.begin(), confidence.end()) - confidence.begin());
}

std::string bestCategory(const std::vector<std::string>& categories, const std::vector<double>& confidence) {
  const int best = bestIndex(confidence);
  return best < 0 || best >= static_cast<int>(categories.size()) ? std::string() : categories[best];
}

double confidenceOf(const std::vector<std::string>& categories, const std::vector<double>& confidence,
                    const std::string& category) {
  for (std::size_t j = 0; j < categories.size() && j < confidence.size(); ++j)
    if (categories[j] == category) return confidence[j];
  return 0.0;
}

}  // namespace

HypothesisFusion::Hypothesis& HypothesisFusion::hypothesisFor(const std::string& object_id) {
  // By index: a search through the list for each id was quadratic in the
  // objects (hundreds of ids a tick against 450 hypotheses).
  const auto [it, created] = hypothesis_index_.try_emplace(object_id, hypotheses_.size());
  if (!created) return hypotheses_[it->second];
  hypotheses_.push_back(Hypothesis{});
  hypotheses_.back().object_id = object_id;
  return hypotheses_.back();
}

void HypothesisFusion::update(const TickEvidence& evidence) {
  if (evidence.scene == nullptr) throw std::invalid_argument("fusion needs the scene of the tick");
  const scene_objects_t& scene = *evidence.scene;
  const int64_t utime = scene.utime;
  categories_ = scene.categories;

  const auto& scene_index = scene_positions_.of(scene.objects, &scene_object_t::id);
  std::unordered_map<std::string, int> visible_pixels;
  if (evidence.vision != nullptr)
    for (const auto& p : evidence.vision->percepts) visible_pixels[p.object_id] = p.visible_pixels;

  // Visual evidence needs visible pixels (or, without VISION, v_P > 0).
  auto visuallyPerceived = [&](const object_labels_t& entry) {
    if (evidence.vision == nullptr) return entry.perceptibility > 0;
    const auto it = visible_pixels.find(entry.object_id);
    return it != visible_pixels.end() && it->second > 0;
  };

  // New hypotheses of this tick, created in scenario order.
  std::set<std::pair<std::size_t, std::string>> perceived;
  auto note = [&](const std::string& id) {
    const auto it = scene_index.find(id);
    perceived.insert({it == scene_index.end() ? scene.objects.size() : it->second, id});
  };
  if (evidence.visual_labels != nullptr)
    for (const auto& entry : evidence.visual_labels->objects)
      if (visuallyPerceived(entry)) note(entry.object_id);
  if (evidence.acoustic_labels != nullptr)
    for (const auto& entry : evidence.acoustic_labels->objects) note(entry.object_id);
  if (evidence.audio != nullptr)
    for (const auto& percept : evidence.audio->percepts) note(percept.object_id);
  for (const auto& [index, id] : perceived) hypothesisFor(id);

  if (evidence.visual_labels != nullptr) {
    for (const auto& entry : evidence.visual_labels->objects) {
      if (!visuallyPerceived(entry)) continue;
      Hypothesis& h = hypothesisFor(entry.object_id);
      if (!h.visual || entry.perceptibility >= h.visual->perceptibility)
        h.visual = Evidence{entry.perceptibility, entry.categories, entry.confidence};
      const auto it = scene_index.find(entry.object_id);
      if (it != scene_index.end()) {
        const auto& object = scene.objects[it->second];
        h.visual_position = Position{object.x, object.y, object.z};
      }
      if (!h.seen && entry.perceptibility >= config_.seen_threshold) {
        h.seen = true;
        h.first_seen_utime = utime;
      }
    }
  }
  auto markHeard = [&](Hypothesis& h) {
    if (h.heard) return;
    h.heard = true;
    h.first_heard_utime = utime;
  };
  if (evidence.acoustic_labels != nullptr) {
    for (const auto& entry : evidence.acoustic_labels->objects) {
      Hypothesis& h = hypothesisFor(entry.object_id);
      if (!h.acoustic || entry.perceptibility >= h.acoustic->perceptibility)
        h.acoustic = Evidence{entry.perceptibility, entry.categories, entry.confidence};
      markHeard(h);
    }
  }
  if (evidence.audio != nullptr) {
    for (const auto& percept : evidence.audio->percepts) {
      Hypothesis& h = hypothesisFor(percept.object_id);
      h.acoustic_position = Position{percept.est_x, percept.est_y, percept.est_z, percept.located != 0};
      markHeard(h);
    }
  }

  for (auto& h : hypotheses_) {
    if (h.settled_utime >= 0 || !h.seen || !h.heard) continue;
    const bool seen_as_known = h.visual || !h.restored_seen_as.empty();  // seen implies a clear enough view
    const bool heard_as_known = h.acoustic || !h.restored_heard_as.empty();
    if (seen_as_known && heard_as_known) h.settled_utime = utime;  // verified or falsified from now on
  }
}

void HypothesisFusion::restore(const hypotheses_t& previous) {
  if (!hypotheses_.empty()) return;
  for (const auto& p : previous.hypotheses) {
    Hypothesis& h = hypothesisFor(p.object_id);
    h.seen = p.seen;
    h.heard = p.heard;
    h.first_seen_utime = p.first_seen_utime;
    h.first_heard_utime = p.first_heard_utime;
    h.settled_utime = p.settled_utime;
    (p.seen ? h.visual_position : h.acoustic_position) = Position{p.x, p.y, p.z, p.located != 0};
    h.restored = Evidence{p.confidence, p.categories, p.fused};
    h.restored_seen_as = p.seen_as;
    h.restored_heard_as = p.heard_as;
  }
  if (categories_.empty() && !previous.hypotheses.empty()) categories_ = previous.hypotheses.front().categories;
}

void HypothesisFusion::writeMessage(const Hypothesis& h, const std::vector<std::string>& categories,
                                    hypothesis_t& out) const {
  out.object_id = h.object_id;
  const Position position = h.visual_position ? *h.visual_position
                            : h.acoustic_position ? *h.acoustic_position
                                                  : Position{};
  out.x = position.x;
  out.y = position.y;
  out.z = position.z;
  out.located = position.located;

  // The evidence fused: each modality's memory; after a restart the fused
  // confidences published before stand in (once) for a modality that has
  // perceived the object but has no new evidence since.
  std::array<const Evidence*, 3> sources{};  // no allocation per hypothesis and tick
  std::size_t source_count = 0;
  if (h.visual) sources[source_count++] = &*h.visual;
  if (h.acoustic) sources[source_count++] = &*h.acoustic;
  if (h.restored && ((h.seen && !h.visual) || (h.heard && !h.acoustic) || source_count == 0))
    sources[source_count++] = &*h.restored;
  double total = 0;
  const Evidence* clearest = nullptr;
  for (std::size_t s = 0; s < source_count; ++s) {
    const Evidence* e = sources[s];
    total += e->perceptibility;
    if (!clearest || e->perceptibility > clearest->perceptibility) clearest = e;
  }
  out.categories = categories;
  out.fused.clear();
  for (const auto& category : categories) {
    double weighted = 0, plain = 0;
    for (std::size_t s = 0; s < source_count; ++s) {
      const Evidence* e = sources[s];
      const double confidence = confidenceOf(e->categories, e->confidence, category);
      weighted += e->perceptibility * confidence;
      plain += confidence;
    }
    const double mean = source_count == 0 ? 0.5 : plain / source_count;
    double fused = mean;
    if (config_.rule == FusionRule::WeightedMean && total > 0) fused = weighted / total;  // else: the plain mean
    if (config_.rule == FusionRule::Clearest && clearest)
      fused = confidenceOf(clearest->categories, clearest->confidence, category);
    out.fused.push_back(fused);
  }
  out.num_categories = static_cast<int32_t>(out.categories.size());
  const int best = bestIndex(out.fused);
  out.best_category = best < 0 ? "" : out.categories[best];
  out.confidence = best < 0 ? 0.0 : out.fused[best];

  out.seen = h.seen;
  out.heard = h.heard;
  // After a restart, new visual evidence decides only once it is clear enough to count as seen.
  const bool new_visual_decides =
      h.visual && (h.restored_seen_as.empty() || h.visual->perceptibility >= config_.seen_threshold);
  out.seen_as = !h.seen                ? ""
                : new_visual_decides   ? bestCategory(h.visual->categories, h.visual->confidence)
                                       : h.restored_seen_as;
  out.heard_as =
      !h.heard ? "" : h.acoustic ? bestCategory(h.acoustic->categories, h.acoustic->confidence) : h.restored_heard_as;
  const bool both = !out.seen_as.empty() && !out.heard_as.empty();
  out.verified = both && out.seen_as == out.heard_as;
  out.falsified = both && out.seen_as != out.heard_as;
  out.first_heard_utime = h.first_heard_utime;
  out.first_seen_utime = h.first_seen_utime;
  out.settled_utime = h.settled_utime;
}

hypotheses_t HypothesisFusion::hypotheses(int64_t utime, int64_t tick) const {
  hypotheses_t out{};
  writeHypotheses(utime, tick, out);
  return out;
}

void HypothesisFusion::writeHypotheses(int64_t utime, int64_t tick, hypotheses_t& out) const {
  out.utime = utime;
  out.tick = tick;
  out.hypotheses.resize(hypotheses_.size());
  for (std::size_t i = 0; i < hypotheses_.size(); ++i) writeMessage(hypotheses_[i], categories_, out.hypotheses[i]);
  out.num_hypotheses = static_cast<int32_t>(out.hypotheses.size());
}

}  // namespace beft::fusion

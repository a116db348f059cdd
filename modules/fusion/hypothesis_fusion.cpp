#include "hypothesis_fusion.hpp"

#include <algorithm>
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
  for (auto& h : hypotheses_)
    if (h.object_id == object_id) return h;
  hypotheses_.push_back(Hypothesis{});
  hypotheses_.back().object_id = object_id;
  return hypotheses_.back();
}

void HypothesisFusion::update(const TickEvidence& evidence) {
  if (evidence.scene == nullptr) throw std::invalid_argument("fusion needs the scene of the tick");
  const scene_objects_t& scene = *evidence.scene;
  const int64_t utime = scene.utime;
  categories_ = scene.categories;

  std::unordered_map<std::string, std::size_t> scene_index;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) scene_index[scene.objects[i].id] = i;
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
      h.acoustic_position = Position{percept.est_x, percept.est_y, percept.est_z};
      markHeard(h);
    }
  }

  for (auto& h : hypotheses_) {
    if (h.settled_utime >= 0 || !h.seen || !h.heard || !h.visual || !h.acoustic) continue;
    h.settled_utime = utime;  // verified or falsified from now on
  }
}

hypothesis_t HypothesisFusion::toMessage(const Hypothesis& h, const std::vector<std::string>& categories) const {
  hypothesis_t out;
  out.object_id = h.object_id;
  const Position position = h.visual_position ? *h.visual_position
                            : h.acoustic_position ? *h.acoustic_position
                                                  : Position{};
  out.x = position.x;
  out.y = position.y;
  out.z = position.z;

  const double visual_weight = h.visual ? h.visual->perceptibility : 0.0;
  const double acoustic_weight = h.acoustic ? h.acoustic->perceptibility : 0.0;
  const double total = visual_weight + acoustic_weight;
  out.categories = categories;
  for (const auto& category : categories) {
    const double visual = h.visual ? confidenceOf(h.visual->categories, h.visual->confidence, category) : 0.0;
    const double acoustic =
        h.acoustic ? confidenceOf(h.acoustic->categories, h.acoustic->confidence, category) : 0.0;
    double fused = 0;
    if (total > 0) {
      fused = (visual_weight * visual + acoustic_weight * acoustic) / total;
    } else {  // perceived only at zero perceptibility: plain average
      const int sources = (h.visual ? 1 : 0) + (h.acoustic ? 1 : 0);
      fused = sources > 0 ? (visual + acoustic) / sources : 0.5;
    }
    out.fused.push_back(fused);
  }
  out.num_categories = static_cast<int32_t>(out.categories.size());
  const int best = bestIndex(out.fused);
  out.best_category = best < 0 ? "" : out.categories[best];
  out.confidence = best < 0 ? 0.0 : out.fused[best];

  out.seen = h.seen;
  out.heard = h.heard;
  out.seen_as = h.seen && h.visual ? bestCategory(h.visual->categories, h.visual->confidence) : "";
  out.heard_as = h.heard && h.acoustic ? bestCategory(h.acoustic->categories, h.acoustic->confidence) : "";
  const bool both = !out.seen_as.empty() && !out.heard_as.empty();
  out.verified = both && out.seen_as == out.heard_as;
  out.falsified = both && out.seen_as != out.heard_as;
  out.first_heard_utime = h.first_heard_utime;
  out.first_seen_utime = h.first_seen_utime;
  out.settled_utime = h.settled_utime;
  return out;
}

hypotheses_t HypothesisFusion::hypotheses(int64_t utime, int64_t tick) const {
  hypotheses_t out;
  out.utime = utime;
  out.tick = tick;
  for (const auto& h : hypotheses_) out.hypotheses.push_back(toMessage(h, categories_));
  out.num_hypotheses = static_cast<int32_t>(out.hypotheses.size());
  return out;
}

}  // namespace beft::fusion

#include "hypothesis_changes.hpp"

#include <string>
#include <unordered_map>

namespace beft::wire {

bool sameHypothesis(const hypothesis_t& a, const hypothesis_t& b) {
  return a.object_id == b.object_id && a.x == b.x && a.y == b.y && a.z == b.z &&
         a.best_category == b.best_category && a.confidence == b.confidence && a.categories == b.categories &&
         a.fused == b.fused && a.seen == b.seen && a.heard == b.heard && a.seen_as == b.seen_as &&
         a.heard_as == b.heard_as && a.verified == b.verified && a.falsified == b.falsified &&
         a.first_heard_utime == b.first_heard_utime && a.first_seen_utime == b.first_seen_utime &&
         a.settled_utime == b.settled_utime;
}

hypothesis_changes_t changesSince(const hypotheses_t& keyframe, const hypotheses_t& whole) {
  std::unordered_map<std::string, const hypothesis_t*> before;
  before.reserve(keyframe.hypotheses.size());
  for (const auto& h : keyframe.hypotheses) before.emplace(h.object_id, &h);
  hypothesis_changes_t changes{};
  changes.utime = whole.utime;
  changes.tick = whole.tick;
  changes.keyframe_tick = keyframe.tick;
  changes.num_hypotheses = static_cast<int32_t>(whole.hypotheses.size());
  for (const auto& h : whole.hypotheses) {
    const auto it = before.find(h.object_id);
    if (it == before.end() || !sameHypothesis(*it->second, h)) changes.changed.push_back(h);
  }
  changes.num_changed = static_cast<int32_t>(changes.changed.size());
  return changes;
}

bool applyChanges(const hypotheses_t& keyframe, const hypothesis_changes_t& changes, hypotheses_t& whole) {
  if (changes.keyframe_tick != keyframe.tick) return false;
  std::unordered_map<std::string, std::size_t> index;
  index.reserve(keyframe.hypotheses.size());
  for (std::size_t i = 0; i < keyframe.hypotheses.size(); ++i) index.emplace(keyframe.hypotheses[i].object_id, i);
  hypotheses_t result = keyframe;
  for (const auto& h : changes.changed) {
    const auto it = index.find(h.object_id);
    if (it != index.end()) {
      result.hypotheses[it->second] = h;
    } else {
      index.emplace(h.object_id, result.hypotheses.size());
      result.hypotheses.push_back(h);
    }
  }
  if (result.hypotheses.size() != static_cast<std::size_t>(changes.num_hypotheses)) return false;
  result.num_hypotheses = changes.num_hypotheses;
  result.utime = changes.utime;
  result.tick = changes.tick;
  whole = std::move(result);
  return true;
}

}  // namespace beft::wire

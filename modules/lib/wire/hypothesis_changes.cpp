#include "lib/wire/hypothesis_changes.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace beft::wire {

bool sameHypothesis(const hypothesis_t& a, const hypothesis_t& b) {
  return a.object_id == b.object_id && a.x == b.x && a.y == b.y && a.z == b.z && a.located == b.located &&
         a.best_category == b.best_category && a.confidence == b.confidence && a.categories == b.categories &&
         a.fused == b.fused && a.seen == b.seen && a.heard == b.heard && a.seen_as == b.seen_as &&
         a.heard_as == b.heard_as && a.verified == b.verified && a.falsified == b.falsified &&
         a.first_heard_utime == b.first_heard_utime && a.first_seen_utime == b.first_seen_utime &&
         a.settled_utime == b.settled_utime;
}

hypothesis_changes_t changesSince(const hypotheses_t& keyframe, const hypotheses_t& whole) {
  hypothesis_changes_t changes{};
  changes.utime = whole.utime;
  changes.tick = whole.tick;
  changes.keyframe_tick = keyframe.tick;
  changes.num_hypotheses = static_cast<int32_t>(whole.hypotheses.size());
  // The fusion expert only appends: the keyframe's hypotheses usually begin
  // the list in the same order, and are compared pairwise without a lookup.
  const std::size_t shared = std::min(keyframe.hypotheses.size(), whole.hypotheses.size());
  std::size_t same_order = 0;
  while (same_order < shared && keyframe.hypotheses[same_order].object_id == whole.hypotheses[same_order].object_id)
    ++same_order;
  if (same_order == keyframe.hypotheses.size()) {
    for (std::size_t i = 0; i < whole.hypotheses.size(); ++i)
      if (i >= same_order || !sameHypothesis(keyframe.hypotheses[i], whole.hypotheses[i]))
        changes.changed.push_back(whole.hypotheses[i]);
    changes.num_changed = static_cast<int32_t>(changes.changed.size());
    return changes;
  }
  std::unordered_map<std::string, const hypothesis_t*> before;
  before.reserve(keyframe.hypotheses.size());
  for (const auto& h : keyframe.hypotheses) before.emplace(h.object_id, &h);
  for (const auto& h : whole.hypotheses) {
    const auto it = before.find(h.object_id);
    if (it == before.end() || !sameHypothesis(*it->second, h)) changes.changed.push_back(h);
  }
  changes.num_changed = static_cast<int32_t>(changes.changed.size());
  return changes;
}

bool applyChanges(const hypotheses_t& keyframe, const hypothesis_changes_t& changes, hypotheses_t& whole) {
  if (changes.keyframe_tick != keyframe.tick) return false;
  // Where each change goes, before anything is written (a refusal leaves
  // `whole` untouched): over the keyframe's entry of its id (the first, if
  // several), or over an earlier change's new entry, or appended.
  std::vector<std::pair<std::string_view, std::size_t>> by_id;  // one allocation, not one per hypothesis
  by_id.reserve(keyframe.hypotheses.size());
  for (std::size_t i = 0; i < keyframe.hypotheses.size(); ++i) by_id.emplace_back(keyframe.hypotheses[i].object_id, i);
  std::stable_sort(by_id.begin(), by_id.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::size_t> target(changes.changed.size());
  std::vector<std::size_t> appended;  // indices into changes.changed of the new ids
  std::size_t size = keyframe.hypotheses.size();
  for (std::size_t c = 0; c < changes.changed.size(); ++c) {
    const std::string& id = changes.changed[c].object_id;
    const auto it = std::lower_bound(by_id.begin(), by_id.end(), id,
                                     [](const auto& entry, const std::string& key) { return entry.first < key; });
    if (it != by_id.end() && it->first == id) {
      target[c] = it->second;
      continue;
    }
    const auto earlier = std::find_if(appended.begin(), appended.end(),
                                      [&](std::size_t a) { return changes.changed[a].object_id == id; });
    target[c] = earlier != appended.end() ? target[*earlier] : size++;
    if (earlier == appended.end()) appended.push_back(c);
  }
  if (size != static_cast<std::size_t>(changes.num_hypotheses)) return false;
  // Written over the list there was: its strings and arrays are reused.
  whole.hypotheses = keyframe.hypotheses;
  whole.hypotheses.resize(size);
  for (std::size_t c = 0; c < changes.changed.size(); ++c) whole.hypotheses[target[c]] = changes.changed[c];
  whole.num_hypotheses = changes.num_hypotheses;
  whole.utime = changes.utime;
  whole.tick = changes.tick;
  return true;
}

}  // namespace beft::wire

// Looking up the items of a message's list by their id:
// - IdIndex: the item itself, rebuilt at every firing without copying an id
//   (it holds views of the ids, so the list must outlive it and stay
//   unchanged until the next rebuild);
// - IdPositions: the item's place in the list, kept from one firing to the
//   next and made again only when the ids, in order, change (a scene's
//   objects rarely do).
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace beft::expert {

template <typename Item>
class IdIndex {
 public:
  // Over items; of items sharing an id, the last one is found.
  void rebuild(const std::vector<Item>& items, const std::string Item::*id) {
    by_id_.clear();
    by_id_.reserve(items.size());
    for (const Item& item : items) by_id_[std::string_view(item.*id)] = &item;
  }
  // The item with this id, nullptr if none.
  const Item* find(std::string_view id) const {
    const auto it = by_id_.find(id);
    return it == by_id_.end() ? nullptr : it->second;
  }

 private:
  std::unordered_map<std::string_view, const Item*> by_id_;
};

template <typename Item>
class IdPositions {
 public:
  using Positions = std::unordered_map<std::string, std::size_t>;
  // Of items sharing an id, the last place counts.
  const Positions& of(const std::vector<Item>& items, const std::string Item::*id) {
    bool same = ids_.size() == items.size();
    for (std::size_t i = 0; same && i < items.size(); ++i) same = ids_[i] == items[i].*id;
    if (same) return positions_;
    ids_.clear();
    positions_.clear();
    positions_.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
      ids_.push_back(items[i].*id);
      positions_[items[i].*id] = i;
    }
    return positions_;
  }

 private:
  std::vector<std::string> ids_;  // what positions_ was made of
  Positions positions_;
};

}  // namespace beft::expert

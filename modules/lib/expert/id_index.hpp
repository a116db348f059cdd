// The items of a message's list looked up by their id, rebuilt at every
// firing without copying an id: the index holds views of the ids, so the list
// must outlive it and stay unchanged until the next rebuild.
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

}  // namespace beft::expert

// Explored states of a net, each a fixed-width row of int32 (tokens per
// place, and whatever else a search keeps), stored in one flat array and
// found again by hash: a million markings of a few dozen places fit in
// tens of megabytes.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

namespace beft::arbiter {

class StateStore {
 public:
  explicit StateStore(size_t width)
      : width_(width), index_(1024, Hash{this}, Equal{this}) {}

  size_t size() const { return count_; }
  const int32_t* at(size_t i) const { return data_.data() + i * width_; }

  // Adds the state unless present; returns its index and whether it is new.
  std::pair<uint32_t, bool> insert(const std::vector<int32_t>& state) {
    data_.insert(data_.end(), state.begin(), state.end());
    const auto candidate = static_cast<uint32_t>(count_);
    ++count_;
    const auto [it, inserted] = index_.insert(candidate);
    if (!inserted) {
      --count_;
      data_.resize(count_ * width_);
    }
    return {*it, inserted};
  }

 private:
  struct Hash {
    const StateStore* store;
    size_t operator()(uint32_t i) const {
      const int32_t* s = store->at(i);
      uint64_t h = 1469598103934665603ULL;
      for (size_t k = 0; k < store->width_; ++k) {
        h ^= static_cast<uint32_t>(s[k]);
        h *= 1099511628211ULL;
      }
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };
  struct Equal {
    const StateStore* store;
    bool operator()(uint32_t a, uint32_t b) const {
      return std::equal(store->at(a), store->at(a) + store->width_, store->at(b));
    }
  };

  size_t width_;
  size_t count_ = 0;
  std::vector<int32_t> data_;
  std::unordered_set<uint32_t, Hash, Equal> index_;
};

}  // namespace beft::arbiter

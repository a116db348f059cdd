// The search the explorer picks targets and frontiers with: the cheapest of
// candidates whose exact cost is dear to find (a travel field grown far, lines
// of sight drawn), each known beforehand only by a least cost it may have.
//
// Best first: the candidate of the least possible cost is asked for its cost
// if that is at most a little more than the next candidate's least; when it
// is more, its least rises to that limit and it waits its turn again. The
// search ends when no candidate left can beat the cheapest found, so what is
// far is never looked at when something near is cheaper than it can be. Past
// kUnlimitedFrom a candidate is asked without a limit.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <vector>

namespace beft::exploration {

inline constexpr double kUnlimitedFrom = 256.0;  // [m]

// least[i]: candidate i's least possible cost. ask(i, limit) returns
// candidate i's cost when it is at most `limit` (+infinity: no limit), else
// nothing. Returns the cheapest candidate, the first of equals, or nothing
// when none has a cost; the same as asking every candidate without a limit.
template <typename Ask>
std::optional<std::size_t> cheapestFirst(std::vector<double> least, Ask&& ask) {
  std::vector<uint8_t> above(least.size(), 0);  // the cost is known to be above least, not only at least
  const auto later = [&](std::size_t a, std::size_t b) { return least[a] != least[b] ? least[a] > least[b] : a > b; };
  std::vector<std::size_t> queue(least.size());
  std::iota(queue.begin(), queue.end(), std::size_t{0});
  std::make_heap(queue.begin(), queue.end(), later);
  std::optional<std::size_t> best;
  double best_cost = 0;
  while (!queue.empty()) {
    std::pop_heap(queue.begin(), queue.end(), later);
    const std::size_t i = queue.back();
    queue.pop_back();
    if (best && (least[i] > best_cost || (above[i] && least[i] >= best_cost))) break;
    const double next_least = queue.empty() ? least[i] : least[queue.front()];
    double limit = std::max({next_least, least[i] + std::max(4.0, 0.5 * std::abs(least[i])), 6.0});
    if (best) limit = std::min(limit, best_cost);
    if (limit > kUnlimitedFrom) limit = std::numeric_limits<double>::infinity();
    const std::optional<double> cost = ask(i, limit);
    if (!cost) {
      if (std::isinf(limit)) continue;  // none at all
      least[i] = limit;                 // every cost of it is above the limit
      above[i] = 1;
      queue.push_back(i);
      std::push_heap(queue.begin(), queue.end(), later);
      continue;
    }
    if (!best || *cost < best_cost || (*cost == best_cost && i < *best)) {
      best = i;
      best_cost = *cost;
    }
  }
  return best;
}

}  // namespace beft::exploration

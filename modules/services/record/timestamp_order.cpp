#include "services/record/timestamp_order.hpp"

#include <algorithm>
#include <limits>

namespace beft::record {

void TimestampOrder::add(TimedEvent event) { held_.push_back(std::move(event)); }

std::size_t TimestampOrder::release(int64_t now_us, const std::function<void(const TimedEvent&)>& write) {
  return releaseBefore(now_us - hold_back_us_, write);
}

std::size_t TimestampOrder::releaseAll(const std::function<void(const TimedEvent&)>& write) {
  return releaseBefore(std::numeric_limits<int64_t>::max(), write);
}

std::size_t TimestampOrder::releaseBefore(int64_t limit_us, const std::function<void(const TimedEvent&)>& write) {
  std::stable_sort(held_.begin(), held_.end(),
                   [](const TimedEvent& a, const TimedEvent& b) { return a.utime < b.utime; });
  std::size_t count = 0;
  while (count < held_.size() && held_[count].utime < limit_us) ++count;
  for (std::size_t i = 0; i < count; ++i) write(held_[i]);
  held_.erase(held_.begin(), held_.begin() + static_cast<long>(count));
  return count;
}

}  // namespace beft::record

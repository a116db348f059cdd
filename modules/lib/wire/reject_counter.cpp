#include "lib/wire/reject_counter.hpp"

#include "lib/common/log.hpp"

namespace beft::wire {

void RejectCounter::count(const std::string& channel, const Verdict& verdict, const std::string& reason,
                          Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  ChannelCount& counts = channels_[channel];
  ++counts.total;
  ++faults_[verdict.fault];
  ++counts.since_logged;
  if (counts.logged && now - counts.last_logged < std::chrono::seconds(1)) return;
  log::warn("rejected ", counts.since_logged, counts.since_logged == 1 ? " message" : " messages", " on ", channel,
            counts.logged ? " in the last second" : "", " (latest: ", verdict.text(), reason.empty() ? "" : ": ",
            reason, "); ", counts.total, " on this channel in all");
  counts.logged = true;
  counts.last_logged = now;
  counts.since_logged = 0;
  ++lines_logged_;
}

std::map<std::string, uint64_t> RejectCounter::totals() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::map<std::string, uint64_t> totals;
  for (const auto& [channel, counts] : channels_) totals[channel] = counts.total;
  return totals;
}

uint64_t RejectCounter::total() const {
  std::lock_guard<std::mutex> lock(mutex_);
  uint64_t sum = 0;
  for (const auto& entry : channels_) sum += entry.second.total;
  return sum;
}

uint64_t RejectCounter::totalOf(Fault fault) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto found = faults_.find(fault);
  return found == faults_.end() ? 0 : found->second;
}

std::map<Fault, uint64_t> RejectCounter::faultTotals() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return faults_;
}

uint64_t RejectCounter::linesLogged() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return lines_logged_;
}

RejectCounter& processRejects() {
  static RejectCounter counter;
  return counter;
}

}  // namespace beft::wire

#include "blackboard/snapshot.hpp"

#include <set>

#include "lib/common/channels.hpp"

namespace beft::blackboard {

beft::bb_snapshot_t buildSnapshot(const Store& store, const beft::bb_query_t& query, int64_t now_utime) {
  std::set<std::string> wanted(query.channels.begin(), query.channels.end());
  if (wanted.empty()) {
    const auto all = store.channels();
    wanted.insert(all.begin(), all.end());
  }
  beft::bb_snapshot_t snapshot{};
  snapshot.utime = now_utime;
  snapshot.query_id = query.query_id;
  for (const std::string& channel : wanted) {
    const Store::History::Entry* latest = store.latest(channel);
    if (!latest) continue;
    beft::bb_entry_t entry;
    entry.channel = channel;
    entry.sequence = static_cast<int64_t>(latest->sequence);
    entry.utime = latest->utime;
    entry.data = latest->message;
    entry.data_size = static_cast<int32_t>(entry.data.size());
    snapshot.entries.push_back(std::move(entry));
  }
  snapshot.num_entries = static_cast<int32_t>(snapshot.entries.size());
  return snapshot;
}

std::vector<std::string> missingChannels(const Store& store, const beft::bb_query_t& query) {
  std::set<std::string> missing;
  for (const std::string& channel : query.channels)
    if (!store.latest(channel)) missing.insert(channel);
  return {missing.begin(), missing.end()};
}

std::string snapshotChannel(const std::string& requester) {
  return std::string(channels::kBlackboardSnapshotPrefix) + requester;
}

}  // namespace beft::blackboard

#include "blackboard/store.hpp"

namespace beft::blackboard {

std::optional<int64_t> encodedUtime(const void* data, int size) {
  if (!data || size < 16) return std::nullopt;
  const auto* bytes = static_cast<const uint8_t*>(data) + 8;
  uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value = (value << 8) | bytes[i];
  return static_cast<int64_t>(value);
}

Store::Store(Limits limits) : limits_(limits) {
  if (limits_.history == 0) limits_.history = 1;
}

std::optional<uint64_t> Store::store(const std::string& channel, const void* data, int size) {
  const auto utime = encodedUtime(data, size);
  if (!utime) {
    ++messages_rejected_;
    return std::nullopt;
  }
  auto it = channels_.find(channel);
  if (it == channels_.end()) it = channels_.emplace(channel, Channel{History(limits_.history), 0}).first;
  Channel& entry = it->second;

  // ChannelHistory drops the oldest itself when full: account for its bytes first.
  if (entry.history.size() == entry.history.capacity()) {
    const std::size_t dropped = entry.history.oldest()->message.size();
    entry.bytes -= dropped;
    bytes_held_ -= dropped;
  }
  const auto* begin = static_cast<const uint8_t*>(data);
  const uint64_t sequence = entry.history.store(Bytes(begin, begin + size), *utime);
  entry.bytes += static_cast<std::size_t>(size);
  bytes_held_ += static_cast<std::size_t>(size);

  while (entry.bytes > limits_.max_channel_bytes && entry.history.size() > 1) {
    const std::size_t dropped = entry.history.oldest()->message.size();
    entry.history.dropOldest();
    entry.bytes -= dropped;
    bytes_held_ -= dropped;
  }
  ++messages_stored_;
  return sequence;
}

const Store::History* Store::history(const std::string& channel) const {
  auto it = channels_.find(channel);
  return it == channels_.end() ? nullptr : &it->second.history;
}

const Store::History::Entry* Store::latest(const std::string& channel) const {
  const History* found = history(channel);
  return found ? found->latest() : nullptr;
}

std::vector<std::string> Store::channels() const {
  std::vector<std::string> names;
  names.reserve(channels_.size());
  for (const auto& entry : channels_) names.push_back(entry.first);
  return names;
}

}  // namespace beft::blackboard

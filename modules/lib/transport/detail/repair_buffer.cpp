#include "lib/transport/detail/repair_buffer.hpp"

namespace beft::transport::detail {

uint64_t RepairBuffer::nextSequence(const std::string& channel) { return channels_[channel].last_sequence + 1; }

int64_t RepairBuffer::streamStart(const std::string& channel, int64_t now_us) const {
  const auto found = channels_.find(channel);
  return found == channels_.end() || found->second.stream_start_us == 0 ? now_us : found->second.stream_start_us;
}

void RepairBuffer::keep(const std::string& channel, uint64_t sequence, std::vector<uint8_t> bytes,
                        int64_t stream_start_us) {
  Channel& kept = channels_[channel];
  if (kept.stream_start_us == 0) kept.stream_start_us = stream_start_us;
  if (sequence > kept.last_sequence) kept.last_sequence = sequence;
  bytes_kept_ += bytes.size();
  kept.kept[sequence] = std::make_shared<const std::vector<uint8_t>>(std::move(bytes));
  order_.emplace_back(channel, sequence);
  evictOverBudget();
}

void RepairBuffer::evictOverBudget() {
  // The newest message of a channel stays (it goes to the back of the
  // queue): a receiver that missed a channel's last message asks for it.
  for (std::size_t looked = order_.size(); bytes_kept_ > budget_bytes_ && looked > 0; --looked) {
    auto oldest = std::move(order_.front());
    order_.pop_front();
    Channel& kept = channels_[oldest.first];
    if (oldest.second == kept.last_sequence) {
      order_.push_back(std::move(oldest));
      continue;
    }
    const auto found = kept.kept.find(oldest.second);
    if (found == kept.kept.end()) continue;
    bytes_kept_ -= found->second->size();
    kept.kept.erase(found);
  }
}

std::shared_ptr<const std::vector<uint8_t>> RepairBuffer::find(const std::string& channel, uint64_t sequence) const {
  const auto channel_at = channels_.find(channel);
  if (channel_at == channels_.end()) return nullptr;
  const auto found = channel_at->second.kept.find(sequence);
  return found == channel_at->second.kept.end() ? nullptr : found->second;
}

std::vector<RepairBuffer::ChannelState> RepairBuffer::state() const {
  std::vector<ChannelState> states;
  states.reserve(channels_.size());
  for (const auto& [name, channel] : channels_) {
    const uint64_t first_kept = channel.kept.empty() ? channel.last_sequence + 1 : channel.kept.begin()->first;
    states.push_back({name, channel.last_sequence, first_kept, channel.stream_start_us});
  }
  return states;
}

}  // namespace beft::transport::detail

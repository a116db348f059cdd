#include "lib/transport/detail/lcm_wire.hpp"

#include <cstring>

namespace beft::lcm_wire {

namespace {

uint32_t readBig32(const uint8_t* at) {
  return (uint32_t{at[0]} << 24) | (uint32_t{at[1]} << 16) | (uint32_t{at[2]} << 8) | uint32_t{at[3]};
}

uint16_t readBig16(const uint8_t* at) { return static_cast<uint16_t>((at[0] << 8) | at[1]); }

Packet invalid(std::string why) {
  Packet packet;
  packet.invalid_reason = std::move(why);
  return packet;
}

// The NUL-terminated channel at the start of `bytes`; false if it has no NUL
// within LCM's longest name.
bool readChannel(const uint8_t* bytes, std::size_t size, std::string_view& channel) {
  const std::size_t limit = size < kMaxChannelLength + 1 ? size : kMaxChannelLength + 1;
  const void* nul = std::memchr(bytes, 0, limit);
  if (!nul) return false;
  channel = std::string_view(reinterpret_cast<const char*>(bytes),
                             static_cast<std::size_t>(static_cast<const uint8_t*>(nul) - bytes));
  return true;
}

}  // namespace

Packet parsePacket(const uint8_t* bytes, std::size_t size) {
  if (size < kShortHeaderBytes) return invalid("shorter than an LCM header");
  const uint32_t magic = readBig32(bytes);
  Packet packet;
  packet.sequence = readBig32(bytes + 4);
  if (magic == kMagicShort) {
    const uint8_t* rest = bytes + kShortHeaderBytes;
    const std::size_t rest_size = size - kShortHeaderBytes;
    if (!readChannel(rest, rest_size, packet.channel)) return invalid("channel name without its NUL");
    packet.kind = Packet::Kind::Short;
    packet.payload = rest + packet.channel.size() + 1;
    packet.payload_size = rest_size - packet.channel.size() - 1;
    return packet;
  }
  if (magic != kMagicFragment) return invalid("not an LCM datagram (bad magic)");
  if (size < kFragmentHeaderBytes) return invalid("shorter than an LCM fragment header");
  packet.message_size = readBig32(bytes + 8);
  packet.fragment_offset = readBig32(bytes + 12);
  packet.fragment_index = readBig16(bytes + 16);
  packet.fragment_count = readBig16(bytes + 18);
  if (packet.fragment_count == 0 || packet.fragment_index >= packet.fragment_count)
    return invalid("fragment number out of range");
  if (packet.message_size > kMaxMessageBytes) return invalid("message larger than LCM allows");
  const uint8_t* rest = bytes + kFragmentHeaderBytes;
  std::size_t rest_size = size - kFragmentHeaderBytes;
  if (packet.fragment_index == 0) {
    if (!readChannel(rest, rest_size, packet.channel)) return invalid("channel name without its NUL");
    rest += packet.channel.size() + 1;
    rest_size -= packet.channel.size() + 1;
  }
  if (uint64_t{packet.fragment_offset} + rest_size > packet.message_size)
    return invalid("fragment reaches past the end of its message");
  packet.kind = Packet::Kind::Fragment;
  packet.payload = rest;
  packet.payload_size = rest_size;
  return packet;
}

void FragmentAssembler::dropPartial(std::map<Key, Partial>::iterator which) {
  partial_bytes_ -= which->second.data.size();
  partial_.erase(which);
  ++dropped_incomplete_;
}

bool FragmentAssembler::add(uint64_t sender, const Packet& fragment, int64_t recv_utime, Message& out) {
  const Key key{sender, fragment.sequence};
  auto found = partial_.find(key);
  if (found != partial_.end() && (found->second.data.size() != fragment.message_size ||
                                  found->second.received.size() != fragment.fragment_count)) {
    // The same sequence number for another message: the old one is lost.
    dropPartial(found);
    found = partial_.end();
  }
  if (found == partial_.end()) {
    while (!partial_.empty() &&
           (partial_.size() >= max_partial_ || partial_bytes_ + fragment.message_size > kMaxPartialBytes)) {
      auto oldest = partial_.begin();
      for (auto it = partial_.begin(); it != partial_.end(); ++it)
        if (it->second.age < oldest->second.age) oldest = it;
      dropPartial(oldest);
    }
    Partial fresh;
    fresh.data.resize(fragment.message_size);
    fresh.received.assign(fragment.fragment_count, false);
    fresh.remaining = fragment.fragment_count;
    fresh.age = opened_++;
    partial_bytes_ += fragment.message_size;
    found = partial_.emplace(key, std::move(fresh)).first;
  }
  Partial& partial = found->second;
  if (partial.received[fragment.fragment_index]) {
    ++rejected_fragments_;  // a duplicate
    return false;
  }
  partial.received[fragment.fragment_index] = true;
  --partial.remaining;
  if (fragment.fragment_index == 0) partial.channel.assign(fragment.channel);
  if (fragment.payload_size > 0)
    std::memcpy(partial.data.data() + fragment.fragment_offset, fragment.payload, fragment.payload_size);
  if (partial.remaining > 0) return false;

  done_channel_ = std::move(partial.channel);
  done_data_ = std::move(partial.data);
  partial_bytes_ -= done_data_.size();
  partial_.erase(found);
  out.channel = done_channel_;
  out.data = done_data_.data();
  out.size = done_data_.size();
  out.recv_utime = recv_utime;
  return true;
}

}  // namespace beft::lcm_wire

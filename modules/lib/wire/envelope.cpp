#include "lib/wire/envelope.hpp"

#include <cstring>

namespace beft::wire {

namespace {

constexpr uint8_t kMagic[4] = {'B', 'E', 'N', 'V'};

uint64_t readU64(const uint8_t* at) {
  uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value = (value << 8) | at[i];
  return value;
}

void writeU64(std::vector<uint8_t>& bytes, uint64_t value) {
  for (int shift = 56; shift >= 0; shift -= 8) bytes.push_back(static_cast<uint8_t>(value >> shift));
}

}  // namespace

bool splitEnvelope(const uint8_t* data, std::size_t size, std::size_t& payload_size, Envelope& envelope) {
  payload_size = size;
  if (data == nullptr || size < kEnvelopeBytes) return false;
  if (std::memcmp(data + size - 4, kMagic, 4) != 0) return false;
  const uint8_t tag_size = data[size - 5];
  if (tag_size != 0 && tag_size != kTagBytes) return false;
  const std::size_t total = envelopeBytes(tag_size != 0);
  if (size < total) return false;
  const uint8_t* at = data + size - total;
  envelope.sender = readU64(at);
  envelope.stream_start_us = static_cast<int64_t>(readU64(at + 8));
  envelope.sequence = readU64(at + 16);
  envelope.tagged = tag_size != 0;
  if (envelope.tagged) std::memcpy(envelope.tag.data(), at + 24, kTagBytes);
  payload_size = size - total;
  return true;
}

std::size_t payloadSize(const uint8_t* data, std::size_t size) {
  std::size_t payload_size = size;
  Envelope unused;
  splitEnvelope(data, size, payload_size, unused);
  return payload_size;
}

void appendEnvelope(std::vector<uint8_t>& bytes, const Envelope& envelope) {
  writeU64(bytes, envelope.sender);
  writeU64(bytes, static_cast<uint64_t>(envelope.stream_start_us));
  writeU64(bytes, envelope.sequence);
  if (envelope.tagged) bytes.insert(bytes.end(), envelope.tag.begin(), envelope.tag.end());
  bytes.push_back(envelope.tagged ? static_cast<uint8_t>(kTagBytes) : 0);
  bytes.insert(bytes.end(), kMagic, kMagic + 4);
}

}  // namespace beft::wire

// The envelope every BEFT process puts after a message's encoded bytes: who
// sent it, its number on its channel, and (in a run with a key) a tag that
// proves the sender holds the key.
//
//   payload | sender (8) | stream start (8) | sequence (8) | tag (0 or 16) | tag size (1) | "BENV"
//
// All integers big-endian. LCM's generated decoders (C++, Java: lcm-spy) read
// their fields and ignore what follows, so a message with an envelope decodes
// as one without; the transport takes it off before a handler sees the bytes,
// and the recorder writes messages without it (logs look as they always did).
// A message without an envelope (an old log replayed, a program outside the
// project) is still a message; a run with a key refuses it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace beft::wire {

constexpr std::size_t kTagBytes = 16;

struct Envelope {
  uint64_t sender = 0;          // the publishing process's id, drawn at its start (never 0)
  int64_t stream_start_us = 0;  // when the sender published its first message on the channel [us since the epoch]
  uint64_t sequence = 0;        // per sender and channel, from 1
  bool tagged = false;
  std::array<uint8_t, kTagBytes> tag{};
};

constexpr std::size_t kEnvelopeBytes = 8 + 8 + 8 + 1 + 4;  // without a tag

// The envelope's size when `tagged`.
constexpr std::size_t envelopeBytes(bool tagged) { return kEnvelopeBytes + (tagged ? kTagBytes : 0); }

// When `data` ends with an envelope: fills `envelope`, sets `payload_size`
// to the bytes before it, returns true. Otherwise false and `payload_size`
// is `size`.
bool splitEnvelope(const uint8_t* data, std::size_t size, std::size_t& payload_size, Envelope& envelope);

// The bytes of `size` without an envelope at their end.
std::size_t payloadSize(const uint8_t* data, std::size_t size);

// Appends `envelope` (its tag when tagged) to `bytes`.
void appendEnvelope(std::vector<uint8_t>& bytes, const Envelope& envelope);

}  // namespace beft::wire

// The one way received bytes become a message: the guard first
// (message_check.hpp), then LCM's generated decoder.
//
//   beft::fire_t fire;
//   if (wire::decodeFrom(channel, data, size, fire)) ...   // a refusal is counted under the channel
#pragma once

#include <climits>
#include <cstddef>
#include <cstdint>
#include <string>

#include "lib/wire/envelope.hpp"
#include "lib/wire/message_check.hpp"
#include "lib/wire/reject_counter.hpp"

namespace beft::wire {

// Checks, then decodes into message; the verdict says why not. An envelope
// at the end (envelope.hpp: what a subscriber of LCM's own gets) is left out.
template <typename Message>
Verdict guardedDecode(const void* data, std::size_t size, Message& message) {
  static const uint64_t fingerprint = static_cast<uint64_t>(Message::getHash());
  size = payloadSize(static_cast<const uint8_t*>(data), size);
  if (size > static_cast<std::size_t>(INT_MAX)) return {Fault::kLengthBeyondBytes, ""};
  Verdict verdict = MessageRules::beftTypes().check(fingerprint, data, size);
  if (!verdict.ok()) return verdict;
  if (message.decode(data, 0, static_cast<int>(size)) != static_cast<int>(size)) return {Fault::kUndecodable, ""};
  return verdict;
}

// The guard only, for bytes kept now and decoded later (counted as below).
template <typename Message>
bool validFrom(const std::string& channel, const void* data, std::size_t size) {
  static const uint64_t fingerprint = static_cast<uint64_t>(Message::getHash());
  size = payloadSize(static_cast<const uint8_t*>(data), size);
  const Verdict verdict = MessageRules::beftTypes().check(fingerprint, data, size);
  if (!verdict.ok()) processRejects().count(channel, verdict);
  return verdict.ok();
}

// guardedDecode, with a refusal counted (and logged, at most once a second)
// under the channel in the process's reject counter.
template <typename Message>
bool decodeFrom(const std::string& channel, const void* data, std::size_t size, Message& message) {
  const Verdict verdict = guardedDecode(data, size, message);
  if (!verdict.ok()) processRejects().count(channel, verdict);
  return verdict.ok();
}

}  // namespace beft::wire

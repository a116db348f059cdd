// A run's shared key and the tag it puts on every message (DDS Security and
// SROS2 do the same with their own keys): a keyed BLAKE2b MAC (libsodium's
// crypto_generichash, never crypto written here) over the channel as sent,
// the sender, the sequence number and the payload. A receiver of a keyed run
// refuses a message without a valid tag; a host without the key can neither
// make one nor change a tagged message.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "lib/wire/envelope.hpp"

namespace beft::transport {

class MessageKey {
 public:
  static constexpr std::size_t kBytes = 32;
  // Reads a key file: 32 or more random bytes, or their hexadecimal text.
  // nullopt, with the reason in `why`, when unreadable or too short.
  static std::optional<MessageKey> fromFile(const std::string& path, std::string* why);
  // A new random key, as `beft key new` writes it.
  static MessageKey random();
  explicit MessageKey(const std::array<uint8_t, kBytes>& bytes) : bytes_(bytes) {}
  const std::array<uint8_t, kBytes>& bytes() const { return bytes_; }

 private:
  std::array<uint8_t, kBytes> bytes_{};
};

// The process's key: set by setProcessKey, else read once from the file named
// by BEFT_KEY_FILE; null for a run without one. A BEFT_KEY_FILE that cannot
// be read ends the process with the reason (a keyed run must not run open).
const MessageKey* processKey();
void setProcessKey(std::optional<MessageKey> key);

// The tag of a message: channel (as sent, with its run suffix), sender,
// sequence number, payload.
std::array<uint8_t, wire::kTagBytes> tagOf(const MessageKey& key, std::string_view channel, uint64_t sender,
                                           uint64_t sequence, const uint8_t* payload, std::size_t size);

// True when `envelope` carries the tag of that message (compared in constant time).
bool tagValid(const MessageKey& key, std::string_view channel, const wire::Envelope& envelope, const uint8_t* payload,
              std::size_t size);

}  // namespace beft::transport

// What happens to a datagram on a bad network or from a buggy program: the
// damage beft-inject does to copies of a run's messages.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace beft::inject {

enum class Damage {
  kBitFlips,         // a few bits flipped anywhere (may still decode)
  kTruncated,        // cut short
  kJunkAppended,     // trailing bytes
  kForeignType,      // another type's fingerprint
  kWrongChannel,     // a valid message of one channel sent on another
  kWordsOverwritten, // random 32-bit words written over it (lengths, counts)
};

const std::vector<Damage>& everyDamage();
// The kinds that never decode as the channel's type (truncation, junk,
// foreign fingerprint, another channel's type): malformed for certain.
const std::vector<Damage>& malformedDamage();
const char* damageName(Damage damage);
// "bits,truncate,..." -> kinds; "all", "malformed". Throws std::invalid_argument.
std::vector<Damage> parseDamage(const std::string& text);

struct DamagedMessage {
  std::string channel;
  std::vector<uint8_t> data;
};

// One damaged copy. `other` is another message (its channel and type) for
// the kinds that need one.
DamagedMessage damage(const std::string& channel, const std::vector<uint8_t>& data, Damage kind,
                      const DamagedMessage& other, std::mt19937_64& random);

}  // namespace beft::inject

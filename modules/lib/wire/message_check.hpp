// The message guard: encoded bytes checked against their .lcm definition
// before LCM's generated decoder sees them.
//
// LCM 1.3.1's decoders size strings and arrays from the received bytes
// without comparing them with what is left (a negative string length throws
// std::length_error, a count of 2^31 elements std::bad_alloc) and take any
// value. The generated types stay the contract: the guard walks the bytes
// once, from the same .lcm files, without allocating, and refuses a message
// before anything is sized from it. Beyond the layout it checks what the
// .lcm comments declare: every float and double finite (NaN only where the
// comment says "NaN"), booleans 0 or 1, "STATUS_*" fields one of those
// constants, ">= 0" bounds on ticks and ids.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "lib/wire/lcm_schema.hpp"

namespace beft::wire {

enum class Fault : uint8_t {
  kNone,
  kTooShort,           // fewer than 8 bytes: no fingerprint
  kUnknownType,        // the fingerprint is of no beft type
  kWrongType,          // a beft type, but not the one the channel carries
  kLengthBeyondBytes,  // a string or array longer than the bytes left
  kNegativeLength,     // a string or array length below zero (or a string of length 0)
  kBadString,          // not terminated by its NUL, or a NUL inside
  kTrailingBytes,      // bytes left after the message
  kNonFinite,          // infinite, or NaN where NaN is not declared
  kBadBoolean,         // a boolean byte other than 0 or 1
  kBadEnum,            // not one of the declared constants
  kBelowBound,         // below the declared lower bound
  kUndecodable,        // the generated decoder refused what the guard passed
  kBadPayload,         // the payload's own reader refused it (a camera frame's compressed pixels)
  kOtherRun,           // on another run's channel (run_identity.hpp): dropped, not malformed
  kUnauthenticated,    // in a run with a key: no valid tag (lib/transport/message_key.hpp)
};

// "length beyond the bytes", ... (static text)
const char* faultName(Fault fault);

struct Verdict {
  Fault fault = Fault::kNone;
  const char* field = "";  // "hypotheses_t.hypotheses.label" (static storage), or ""
  int64_t other_run = 0;   // kOtherRun: that run's id

  bool ok() const { return fault == Fault::kNone; }
  std::string text() const;  // "hypotheses_t.hypotheses.label: length beyond the bytes"
};

class MessageRules {
 public:
  // Compiles the checks of every struct of a finalized type set. Throws
  // SchemaError when a comment names constants the struct does not have.
  explicit MessageRules(const LcmTypeSet& types);
  ~MessageRules();

  // Every type of lcmtypes/, compiled once on first use. Thread-safe.
  static const MessageRules& beftTypes();

  // A whole encoded message (8-byte fingerprint first) that must be of the
  // type with this fingerprint.
  Verdict check(uint64_t fingerprint, const void* data, std::size_t size) const;
  // The same for whichever known type the message's fingerprint names.
  Verdict checkAnyType(const void* data, std::size_t size) const;
  bool knows(uint64_t fingerprint) const;

  // What a channel must carry: a message of the channel's type (channels.hpp)
  // on a beft channel, any known type elsewhere.
  Verdict checkForChannel(const std::string& channel, const void* data, std::size_t size) const;

 private:
  struct Compiled;
  std::unique_ptr<const Compiled> compiled_;
};

}  // namespace beft::wire

// Readable text of any encoded beft message, found by its fingerprint (the
// 8-byte hash an encoded LCM message starts with) and decoded from the .lcm
// definitions compiled into the library. Shared by beft-blackboard-dump,
// beft-spy and the log tools.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lib/wire/lcm_schema.hpp"

namespace beft::blackboard {

// Layout limits of the readable text.
struct DescribeOptions {
  int max_lines = 60;            // whole text; the rest is counted in a last line
  int max_inline_items = 12;     // items of a number/string array printed on its line
  int max_struct_items = 16;     // elements of a struct array printed in full
  int max_string_chars = 160;    // characters of one string printed
};

class MessageDecoder {
 public:
  // Takes a finalized type set.
  explicit MessageDecoder(wire::LcmTypeSet types);

  // Every type of lcmtypes/, built once on first use. Thread-safe.
  static const MessageDecoder& beftTypes();

  const wire::LcmTypeSet& types() const { return types_; }

  // The type of an encoded message from its fingerprint, or null.
  const wire::LcmStruct* typeOf(const void* data, int size) const;

  // Readable text, one line per field ("name: value"), nested structs
  // indented by two spaces; byte arrays as "<N bytes>", long arrays cut with
  // a count. The channel names the expected type when the fingerprint is
  // unknown. Never throws: undecodable input gives a line saying why.
  std::string describe(const std::string& channel, const void* data, int size,
                       const DescribeOptions& options = {}) const;
  std::vector<std::string> describeLines(const std::string& channel, const void* data, int size,
                                         const DescribeOptions& options = {}) const;

 private:
  wire::LcmTypeSet types_;
};

// The fingerprint an encoded message starts with, if it has 8 bytes.
std::optional<uint64_t> fingerprintOf(const void* data, int size);

// "beft.robot_state_t", or "" when the fingerprint is not a beft type.
std::string typeNameOf(const void* data, int size);

// MessageDecoder::beftTypes().describe with at most max_lines lines.
std::string describeMessage(const std::string& channel, const void* data, int size, int max_lines = 60);

// Shortest text that reads back as the same double ("0.1", "4.2", "1e-07").
std::string formatNumber(double value);

}  // namespace beft::blackboard

// JSON text that never fails to print: bytes as base64 (how Foxglove's JSON
// carries byte arrays), any string made valid UTF-8, and a dump that replaces
// what is not UTF-8 instead of throwing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace beft::foxglove {

// Standard base64 (RFC 4648, with '=' padding).
std::string base64Encode(const uint8_t* data, std::size_t size);
inline std::string base64Encode(std::string_view bytes) {
  return base64Encode(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}

// The bytes of standard base64 text (with its padding), or nullopt when
// text is not that (a length not a multiple of 4, a character outside the
// alphabet, padding before the end).
std::optional<std::string> base64Decode(std::string_view text);

// text with every byte that is not part of a well-formed UTF-8 sequence
// replaced by U+FFFD: JSON strings must be UTF-8, a received string need not be.
std::string validUtf8(std::string_view text);

// Compact JSON text; invalid UTF-8 in strings becomes U+FFFD. Never throws
// for a value built by this library.
std::string dumpJson(const nlohmann::json& value);

}  // namespace beft::foxglove

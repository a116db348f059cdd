#include "tools/inject/message_damage.hpp"

#include <algorithm>
#include <stdexcept>

namespace beft::inject {

const std::vector<Damage>& everyDamage() {
  static const std::vector<Damage> kinds = {Damage::kBitFlips,    Damage::kTruncated,    Damage::kJunkAppended,
                                            Damage::kForeignType, Damage::kWrongChannel, Damage::kWordsOverwritten};
  return kinds;
}

const std::vector<Damage>& malformedDamage() {
  static const std::vector<Damage> kinds = {Damage::kTruncated, Damage::kJunkAppended, Damage::kForeignType,
                                            Damage::kWrongChannel};
  return kinds;
}

const char* damageName(Damage damage) {
  switch (damage) {
    case Damage::kBitFlips: return "bits";
    case Damage::kTruncated: return "truncate";
    case Damage::kJunkAppended: return "junk";
    case Damage::kForeignType: return "foreign";
    case Damage::kWrongChannel: return "channel";
    case Damage::kWordsOverwritten: return "words";
  }
  return "?";
}

std::vector<Damage> parseDamage(const std::string& text) {
  if (text == "all") return everyDamage();
  if (text == "malformed") return malformedDamage();
  std::vector<Damage> kinds;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = text.find(',', start);
    const std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    bool found = false;
    for (Damage kind : everyDamage())
      if (name == damageName(kind)) {
        kinds.push_back(kind);
        found = true;
      }
    if (!found)
      throw std::invalid_argument("unknown damage '" + name + "' (bits, truncate, junk, foreign, channel, words, "
                                  "all, malformed)");
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return kinds;
}

DamagedMessage damage(const std::string& channel, const std::vector<uint8_t>& data, Damage kind,
                      const DamagedMessage& other, std::mt19937_64& random) {
  DamagedMessage out{channel, data};
  auto below = [&random](std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(random() % n); };
  switch (kind) {
    case Damage::kBitFlips: {
      const int flips = 1 + static_cast<int>(below(4));
      for (int i = 0; i < flips && !out.data.empty(); ++i)
        out.data[below(out.data.size())] ^= static_cast<uint8_t>(1u << below(8));
      break;
    }
    case Damage::kTruncated:
      out.data.resize(below(out.data.size()));
      break;
    case Damage::kJunkAppended:
      for (std::size_t i = 0, n = 1 + below(64); i < n; ++i) out.data.push_back(static_cast<uint8_t>(random()));
      break;
    case Damage::kForeignType:
      for (std::size_t i = 0; i < 8 && i < out.data.size(); ++i) out.data[i] = static_cast<uint8_t>(random());
      break;
    case Damage::kWrongChannel: {
      // Another channel's message under this channel's name; of the same type
      // (CAMERA_COLOR on CAMERA_DEPTH) it would be valid, so it gets a trailing byte.
      out.data = other.data;
      const bool same_type = other.data.size() >= 8 && data.size() >= 8 &&
                             std::equal(other.data.begin(), other.data.begin() + 8, data.begin());
      if (same_type) out.data.push_back(0);
      break;
    }
    case Damage::kWordsOverwritten:
      for (int i = 0; i < 3 && out.data.size() >= 12; ++i) {
        const std::size_t at = 8 + below(out.data.size() - 11);
        const uint32_t word = static_cast<uint32_t>(random());
        for (int b = 0; b < 4; ++b) out.data[at + b] = static_cast<uint8_t>(word >> (24 - 8 * b));
      }
      break;
  }
  return out;
}

}  // namespace beft::inject

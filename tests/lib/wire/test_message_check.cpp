// The message guard over every beft type: random valid messages built from
// the .lcm definitions pass and decode to the same bytes; every damage a
// network or another program can do is refused (or, for a flipped value
// that is still valid, decodes) and never throws.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include <beft/fire_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/task_command_t.hpp>

#include "lib/wire/embedded_schemas.hpp"
#include "every_beft_type.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/lcm_schema.hpp"

using namespace beft::wire;

namespace {

const LcmTypeSet& beftSchemas() {
  static const LcmTypeSet types = [] {
    LcmTypeSet set;
    for (const auto& schema : embeddedLcmSchemas()) set.addSchema(schema.file, schema.text);
    set.finalize();
    return set;
  }();
  return types;
}

// Writes a valid encoding of a struct: sizes 0..3, values as the comments allow.
class RandomMessage {
 public:
  explicit RandomMessage(uint32_t seed) : random_(seed) {}

  std::vector<uint8_t> make(const std::string& type) {
    bytes_.clear();
    put(beftSchemas().fingerprint(type), 8);
    writeStruct(*beftSchemas().find(type));
    return bytes_;
  }

 private:
  void put(uint64_t value, int count) {
    for (int i = count - 1; i >= 0; --i) bytes_.push_back(static_cast<uint8_t>(value >> (8 * i)));
  }

  void writeStruct(const LcmStruct& lcm_struct) {
    std::map<std::string, int64_t> sizes;
    for (const LcmMember& member : lcm_struct.members) {
      int64_t count = 1;
      for (const auto& dimension : member.dimensions)
        count *= dimension.variable ? sizes.at(dimension.size) : std::stoll(dimension.size);
      for (int64_t i = 0; i < count; ++i) {
        if (const LcmStruct* inner = beftSchemas().find(member.type)) {
          writeStruct(*inner);
          continue;
        }
        const int64_t value = writePrimitive(lcm_struct, member);
        if (member.dimensions.empty()) sizes[member.name] = value;
      }
    }
  }

  // Returns the integer written (a later array's size, when it is one).
  int64_t writePrimitive(const LcmStruct& lcm_struct, const LcmMember& member) {
    const std::string& type = member.type;
    if (type == "string") {
      const std::string text = std::string("s") + std::to_string(random_() % 1000);
      put(text.size() + 1, 4);
      bytes_.insert(bytes_.end(), text.begin(), text.end());
      bytes_.push_back(0);
      return 0;
    }
    if (type == "double" || type == "float") {
      double value = std::uniform_real_distribution<double>(-1e3, 1e3)(random_);
      if (member.comment.find("NaN") != std::string::npos && random_() % 3 == 0) value = std::nan("");
      uint64_t raw;
      if (type == "double") {
        std::memcpy(&raw, &value, 8);
        put(raw, 8);
      } else {
        const float narrow = static_cast<float>(value);
        uint32_t raw32;
        std::memcpy(&raw32, &narrow, 4);
        put(raw32, 4);
      }
      return 0;
    }
    if (type == "boolean") {
      const int64_t value = random_() % 2;
      put(static_cast<uint64_t>(value), 1);
      return value;
    }
    int64_t value = static_cast<int64_t>(random_() % 4);  // small: it may size an array
    std::smatch match;
    static const std::regex enum_pattern(R"(\b([A-Z][A-Z0-9_]*)_\*)");
    if (std::regex_search(member.comment, match, enum_pattern)) {
      std::vector<int64_t> allowed;
      for (const auto& constant : lcm_struct.constants)
        if (constant.name.rfind(match[1].str() + "_", 0) == 0) allowed.push_back(std::stoll(constant.value));
      value = allowed[random_() % allowed.size()];
    }
    static const std::regex bound_pattern(R"(>=\s*(-?[0-9]+))");
    if (std::regex_search(member.comment, match, bound_pattern)) value += std::stoll(match[1].str());
    const int width = type == "int64_t" ? 8 : type == "int32_t" ? 4 : type == "int16_t" ? 2 : 1;
    put(static_cast<uint64_t>(value), width);
    return value;
  }

  std::mt19937 random_;
  std::vector<uint8_t> bytes_;
};

template <typename Message>
std::vector<uint8_t> encode(const Message& message) {
  std::vector<uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

void setInt32At(std::vector<uint8_t>& bytes, std::size_t offset, int32_t value) {
  for (int i = 0; i < 4; ++i) bytes[offset + i] = static_cast<uint8_t>(static_cast<uint32_t>(value) >> (24 - 8 * i));
}

}  // namespace

TEST(MessageGuard, CompilesEveryBeftTypeWithItsDeclaredRules) {
  const MessageRules& rules = MessageRules::beftTypes();
  ASSERT_EQ(everyBeftType().size(), beftSchemas().typeNames().size());
  for (const auto& name : beftSchemas().typeNames()) EXPECT_TRUE(rules.knows(beftSchemas().fingerprint(name))) << name;
}

TEST(MessageGuard, RandomValidMessagesOfEveryTypePassAndDecodeToTheSameBytes) {
  RandomMessage random(7);
  for (const auto& [type, round_trip] : everyBeftType()) {
    for (int i = 0; i < 50; ++i) {
      const auto bytes = random.make(type);
      const GuardedRoundTrip result = round_trip(bytes);
      ASSERT_TRUE(result.verdict.ok()) << type << ": " << result.verdict.text();
      EXPECT_EQ(result.encoded_again, bytes) << type;
    }
  }
}

TEST(MessageGuard, EveryTruncationAndEveryTrailingByteIsRefused) {
  RandomMessage random(11);
  for (const auto& [type, round_trip] : everyBeftType()) {
    const auto bytes = random.make(type);
    for (std::size_t cut = 0; cut < bytes.size(); ++cut) {
      const std::vector<uint8_t> truncated(bytes.begin(), bytes.begin() + static_cast<long>(cut));
      EXPECT_FALSE(round_trip(truncated).verdict.ok()) << type << " cut at " << cut;
    }
    auto longer = bytes;
    longer.push_back(0);
    EXPECT_EQ(round_trip(longer).verdict.fault, Fault::kTrailingBytes) << type;
  }
}

// What crashed the arbiter and the blackboard: lengths that LCM's decoder
// trusts. Refused, never thrown.
TEST(MessageGuard, AbsurdLengthsAreRefusedBeforeAnythingIsAllocated) {
  beft::fire_t fire{};
  fire.expert = "fusion";
  fire.transition = "t_fusion";
  auto bytes = encode(fire);
  for (int32_t length : {-1, 0, -2147483647, 2147483647, 1 << 30}) {
    auto damaged = bytes;
    setInt32At(damaged, 16, length);  // the expert string's length, after fingerprint and utime
    beft::fire_t decoded{};
    Verdict verdict;
    EXPECT_NO_THROW(verdict = guardedDecode(damaged.data(), damaged.size(), decoded));
    EXPECT_FALSE(verdict.ok()) << length;
    EXPECT_STREQ(verdict.field, "fire_t.expert");
  }

  beft::hypotheses_t hypotheses{};
  auto list = encode(hypotheses);
  for (int32_t count : {-5, 100000000}) {
    auto damaged = list;
    setInt32At(damaged, 24, count);  // num_hypotheses, after fingerprint, utime and tick
    beft::hypotheses_t decoded{};
    Verdict verdict;
    EXPECT_NO_THROW(verdict = guardedDecode(damaged.data(), damaged.size(), decoded));
    EXPECT_EQ(verdict.fault, count < 0 ? Fault::kNegativeLength : Fault::kLengthBeyondBytes);
    EXPECT_STREQ(verdict.field, "hypotheses_t.hypotheses");
  }
}

TEST(MessageGuard, AnotherTypesFingerprintAndUnknownFingerprintsAreNamed) {
  beft::fire_t fire{};
  const auto bytes = encode(fire);
  beft::hypotheses_t hypotheses{};
  EXPECT_EQ(guardedDecode(bytes.data(), bytes.size(), hypotheses).fault, Fault::kWrongType);
  auto foreign = bytes;
  foreign[0] ^= 0x5a;
  EXPECT_EQ(guardedDecode(foreign.data(), foreign.size(), fire).fault, Fault::kUnknownType);
  EXPECT_EQ(guardedDecode(bytes.data(), 7, fire).fault, Fault::kTooShort);
  EXPECT_EQ(MessageRules::beftTypes().checkForChannel("FIRE", bytes.data(), bytes.size()).fault, Fault::kNone);
  EXPECT_EQ(MessageRules::beftTypes().checkForChannel("HYPOTHESES", bytes.data(), bytes.size()).fault,
            Fault::kWrongType);
  // Off the channel list, any beft type is taken.
  EXPECT_TRUE(MessageRules::beftTypes().checkForChannel("MY_FIRE_COPY", bytes.data(), bytes.size()).ok());
}

TEST(MessageGuard, ValuesAreCheckedAsTheLcmCommentsDeclare) {
  beft::fire_t fire{};
  fire.tick = -3;  // "tick index, >= 0"
  auto bytes = encode(fire);
  beft::fire_t decoded{};
  EXPECT_EQ(guardedDecode(bytes.data(), bytes.size(), decoded).fault, Fault::kBelowBound);

  beft::task_command_t command{};
  command.command = 9;  // COMMAND_* has 0, 1, 2
  bytes = encode(command);
  beft::task_command_t decoded_command{};
  Verdict verdict = guardedDecode(bytes.data(), bytes.size(), decoded_command);
  EXPECT_EQ(verdict.fault, Fault::kBadEnum);
  EXPECT_EQ(verdict.text(), "task_command_t.command: value not among the declared constants");

  command.command = beft::task_command_t::COMMAND_PUSH;
  command.task.x = std::nan("");  // "NaN if not given": allowed
  command.task.status = beft::task_t::STATUS_PENDING;
  bytes = encode(command);
  EXPECT_TRUE(guardedDecode(bytes.data(), bytes.size(), decoded_command).ok());
  command.task.x = INFINITY;
  bytes = encode(command);
  EXPECT_EQ(guardedDecode(bytes.data(), bytes.size(), decoded_command).fault, Fault::kNonFinite);
  command.task.x = 1.0;
  command.task.priority = 0;
  command.task.note = "a";
  bytes = encode(command);
  ASSERT_TRUE(guardedDecode(bytes.data(), bytes.size(), decoded_command).ok());
  bytes[bytes.size() - 2] = 0;  // a NUL inside the last string ("a" -> "\0")
  EXPECT_EQ(guardedDecode(bytes.data(), bytes.size(), decoded_command).fault, Fault::kBadString);
}

// Random damage of random valid messages: whatever decodes is the same
// message again when encoded (no half-decoded state), and nothing throws.
TEST(MessageGuard, RandomDamageNeverThrowsAndWhatPassesIsCanonical) {
  RandomMessage random(23);
  std::mt19937 damage(5);
  int refused = 0, passed = 0;
  for (const auto& [type, round_trip] : everyBeftType()) {
    for (int i = 0; i < 300; ++i) {
      auto bytes = random.make(type);
      switch (damage() % 4) {
        case 0: bytes[damage() % bytes.size()] ^= static_cast<uint8_t>(1u << (damage() % 8)); break;
        case 1: bytes.resize(damage() % bytes.size()); break;
        case 2: for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<uint8_t>(damage())); break;
        default:
          if (bytes.size() >= 12) setInt32At(bytes, 8 + damage() % (bytes.size() - 11), static_cast<int32_t>(damage()));
      }
      GuardedRoundTrip result;
      ASSERT_NO_THROW(result = round_trip(bytes)) << type;
      if (result.verdict.ok()) {
        ++passed;
        EXPECT_EQ(result.encoded_again, bytes) << type;
      } else {
        ++refused;
      }
    }
  }
  EXPECT_GT(refused, 1000);
  EXPECT_GT(passed, 100);  // flipped values that are still valid messages
}

// beft-inject's "malformed" damage is refused by the message guard, every
// time: the robustness tests and benchmark count on it.
#include <gtest/gtest.h>

#include <random>

#include <beft/camera_frame_t.hpp>
#include <beft/fire_t.hpp>

#include "lib/wire/message_check.hpp"
#include "tools/inject/message_damage.hpp"

using namespace beft::inject;

namespace {

template <typename Message>
DamagedMessage encoded(const std::string& channel, const Message& message) {
  DamagedMessage out{channel, std::vector<uint8_t>(static_cast<std::size_t>(message.getEncodedSize()))};
  message.encode(out.data.data(), 0, static_cast<int>(out.data.size()));
  return out;
}

}  // namespace

TEST(MessageDamage, EveryMalformedKindIsRefusedByTheGuard) {
  beft::camera_frame_t frame{};
  frame.width = 4;
  frame.height = 2;
  frame.encoding = beft::camera_frame_t::ENCODING_RGB8;
  frame.data_size = 24;
  frame.data.assign(24, 7);
  beft::fire_t fire{};
  fire.expert = "vision";
  // CAMERA_COLOR and CAMERA_DEPTH carry the same type: the wrong-channel kind must still be malformed.
  const std::vector<DamagedMessage> messages = {encoded("CAMERA_COLOR", frame), encoded("CAMERA_DEPTH", frame),
                                                encoded("FIRE", fire)};
  std::mt19937_64 random(9);
  for (Damage kind : malformedDamage()) {
    for (int i = 0; i < 300; ++i) {
      const auto& original = messages[random() % messages.size()];
      const auto& other = messages[random() % messages.size()];
      const auto damaged = damage(original.channel, original.data, kind, other, random);
      EXPECT_FALSE(beft::wire::MessageRules::beftTypes()
                       .checkForChannel(damaged.channel, damaged.data.data(), damaged.data.size())
                       .ok())
          << damageName(kind) << " on " << original.channel << " from " << other.channel;
    }
  }
}

TEST(MessageDamage, NamesParseAndUnknownOnesAreRefused) {
  EXPECT_EQ(parseDamage("all").size(), everyDamage().size());
  EXPECT_EQ(parseDamage("bits,junk"), (std::vector<Damage>{Damage::kBitFlips, Damage::kJunkAppended}));
  EXPECT_THROW(parseDamage("bits,nonsense"), std::invalid_argument);
}

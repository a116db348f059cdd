// The envelope after a message's bytes, and the copies a sender keeps.
#include <gtest/gtest.h>

#include <beft/fire_t.hpp>

#include "lib/transport/detail/repair_buffer.hpp"
#include "lib/wire/envelope.hpp"
#include "lib/wire/guarded_decode.hpp"

using beft::transport::detail::RepairBuffer;
using beft::wire::Envelope;

namespace {

TEST(Envelope, ComesOffAsItWentOnWithAndWithoutATag) {
  for (bool tagged : {false, true}) {
    std::vector<uint8_t> bytes = {1, 2, 3};
    Envelope envelope;
    envelope.sender = 0x0102030405060708;
    envelope.sequence = 42;
    envelope.tagged = tagged;
    envelope.tag.fill(0x5a);
    beft::wire::appendEnvelope(bytes, envelope);
    EXPECT_EQ(bytes.size(), 3 + beft::wire::envelopeBytes(tagged));
    std::size_t payload = 0;
    Envelope read;
    ASSERT_TRUE(beft::wire::splitEnvelope(bytes.data(), bytes.size(), payload, read));
    EXPECT_EQ(payload, 3u);
    EXPECT_EQ(read.sender, envelope.sender);
    EXPECT_EQ(read.sequence, 42u);
    EXPECT_EQ(read.tagged, tagged);
    if (tagged) EXPECT_EQ(read.tag, envelope.tag);
  }
}

TEST(Envelope, BytesWithoutOneAreTheirOwnPayload) {
  const std::vector<uint8_t> bytes(40, 7);
  std::size_t payload = 0;
  Envelope read;
  EXPECT_FALSE(beft::wire::splitEnvelope(bytes.data(), bytes.size(), payload, read));
  EXPECT_EQ(payload, 40u);
  EXPECT_EQ(beft::wire::payloadSize(bytes.data(), 3), 3u);
}

TEST(Envelope, AGeneratedDecoderAndTheGuardReadAMessageWithAnEnvelope) {
  beft::fire_t fire{};
  fire.expert = "vision";
  fire.transition = "t_vision";
  fire.tick = 7;
  fire.firing_id = 9;
  std::vector<uint8_t> bytes(static_cast<std::size_t>(fire.getEncodedSize()));
  fire.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  Envelope envelope;
  envelope.sender = 1;
  envelope.sequence = 1;
  beft::wire::appendEnvelope(bytes, envelope);
  beft::fire_t decoded;
  EXPECT_GT(decoded.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  beft::fire_t guarded;
  EXPECT_TRUE(beft::wire::guardedDecode(bytes.data(), bytes.size(), guarded).ok());
  EXPECT_EQ(guarded.firing_id, 9);
}

TEST(RepairBuffer, NumbersEachChannelFromOneAndFindsWhatItKeeps) {
  RepairBuffer kept;
  EXPECT_EQ(kept.nextSequence("A"), 1u);
  kept.keep("A", 1, {1});
  kept.keep("A", 2, {2});
  kept.keep("B", 1, {3});
  EXPECT_EQ(kept.nextSequence("A"), 3u);
  ASSERT_TRUE(kept.find("A", 2));
  EXPECT_EQ(*kept.find("A", 2), std::vector<uint8_t>{2});
  EXPECT_FALSE(kept.find("A", 3));
  EXPECT_FALSE(kept.find("C", 1));
}

TEST(RepairBuffer, DropsTheOldestOverItsBudgetButKeepsEachChannelsLast) {
  RepairBuffer kept(100);
  kept.keep("RARE", 1, std::vector<uint8_t>(40));
  for (uint64_t sequence = 1; sequence <= 10; ++sequence) kept.keep("BUSY", sequence, std::vector<uint8_t>(30));
  EXPECT_LE(kept.bytesKept(), 100u);
  EXPECT_TRUE(kept.find("RARE", 1)) << "a channel's last message stays";
  EXPECT_TRUE(kept.find("BUSY", 10));
  EXPECT_FALSE(kept.find("BUSY", 1));
  for (const auto& state : kept.state()) {
    if (state.channel != "BUSY") continue;
    EXPECT_EQ(state.last_sequence, 10u);
    EXPECT_GT(state.first_kept, 1u);
    EXPECT_TRUE(kept.find("BUSY", state.first_kept));
  }
}

}  // namespace

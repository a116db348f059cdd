// LCM's UDP datagram format: parsing short messages and fragments, refusing
// malformed datagrams, and putting fragments back together in any order.
#include "lib/transport/detail/lcm_wire.hpp"

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

using beft::lcm_wire::FragmentAssembler;
using beft::lcm_wire::Message;
using beft::lcm_wire::Packet;
using beft::lcm_wire::parsePacket;

using Bytes = std::vector<uint8_t>;

void putBig32(Bytes& out, uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(value >> shift));
}

void putBig16(Bytes& out, uint16_t value) {
  out.push_back(static_cast<uint8_t>(value >> 8));
  out.push_back(static_cast<uint8_t>(value));
}

Bytes shortDatagram(uint32_t sequence, const std::string& channel, const std::string& payload) {
  Bytes out;
  putBig32(out, beft::lcm_wire::kMagicShort);
  putBig32(out, sequence);
  out.insert(out.end(), channel.begin(), channel.end());
  out.push_back(0);
  out.insert(out.end(), payload.begin(), payload.end());
  return out;
}

// The fragments LCM's publish makes of a large message: the channel in the
// first, each fragment at most `fragment_payload` bytes after its header.
std::vector<Bytes> fragments(uint32_t sequence, const std::string& channel, const std::string& payload,
                             std::size_t fragment_payload) {
  const std::size_t first = fragment_payload - channel.size() - 1;
  const std::size_t count = 1 + (payload.size() - first + fragment_payload - 1) / fragment_payload;
  std::vector<Bytes> out;
  std::size_t offset = 0;
  for (std::size_t index = 0; index < count; ++index) {
    Bytes datagram;
    putBig32(datagram, beft::lcm_wire::kMagicFragment);
    putBig32(datagram, sequence);
    putBig32(datagram, static_cast<uint32_t>(payload.size()));
    putBig32(datagram, static_cast<uint32_t>(offset));
    putBig16(datagram, static_cast<uint16_t>(index));
    putBig16(datagram, static_cast<uint16_t>(count));
    if (index == 0) {
      datagram.insert(datagram.end(), channel.begin(), channel.end());
      datagram.push_back(0);
    }
    const std::size_t size = std::min(index == 0 ? first : fragment_payload, payload.size() - offset);
    datagram.insert(datagram.end(), payload.begin() + static_cast<long>(offset),
                    payload.begin() + static_cast<long>(offset + size));
    offset += size;
    out.push_back(datagram);
  }
  return out;
}

std::string patterned(std::size_t size, int seed) {
  std::string text(size, '\0');
  for (std::size_t i = 0; i < size; ++i) text[i] = static_cast<char>((i * 31 + static_cast<std::size_t>(seed)) % 251);
  return text;
}

std::string asString(const Message& message) {
  return std::string(reinterpret_cast<const char*>(message.data), message.size);
}

Packet parse(const Bytes& datagram) { return parsePacket(datagram.data(), datagram.size()); }

TEST(LcmWire, ParsesAShortMessage) {
  const Bytes datagram = shortDatagram(77, "ROBOT_STATE", "encoded bytes");
  const Packet packet = parse(datagram);
  ASSERT_EQ(packet.kind, Packet::Kind::Short) << packet.invalid_reason;
  EXPECT_EQ(packet.sequence, 77u);
  EXPECT_EQ(packet.channel, "ROBOT_STATE");
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(packet.payload), packet.payload_size), "encoded bytes");
  const Packet empty = parse(shortDatagram(1, "E", ""));
  ASSERT_EQ(empty.kind, Packet::Kind::Short);
  EXPECT_EQ(empty.payload_size, 0u);
}

TEST(LcmWire, ParsesFragmentHeaders) {
  const auto parts = fragments(5, "CAMERA_COLOR", patterned(1000, 1), 300);
  ASSERT_EQ(parts.size(), 4u);
  const Packet first = parse(parts[0]);
  ASSERT_EQ(first.kind, Packet::Kind::Fragment) << first.invalid_reason;
  EXPECT_EQ(first.channel, "CAMERA_COLOR");
  EXPECT_EQ(first.message_size, 1000u);
  EXPECT_EQ(first.fragment_offset, 0u);
  EXPECT_EQ(first.fragment_count, 4);
  EXPECT_EQ(first.payload_size, 300u - 13u);
  const Packet later = parse(parts[2]);
  ASSERT_EQ(later.kind, Packet::Kind::Fragment) << later.invalid_reason;
  EXPECT_TRUE(later.channel.empty());
  EXPECT_EQ(later.fragment_index, 2);
  EXPECT_EQ(later.fragment_offset, 287u + 300u);
}

TEST(LcmWire, RefusesMalformedDatagramsWithAReason) {
  auto reasonOf = [](const Bytes& datagram) {
    const Packet packet = parse(datagram);
    EXPECT_EQ(packet.kind, Packet::Kind::Invalid);
    return packet.invalid_reason;
  };
  EXPECT_NE(reasonOf(Bytes{'L', 'C', '0', '2'}).find("shorter"), std::string::npos);
  EXPECT_NE(reasonOf(Bytes{'H', 'E', 'L', 'L', 'O', '!', '!', '!', 0}).find("magic"), std::string::npos);
  Bytes no_nul = shortDatagram(1, "CHANNEL", "");
  no_nul.pop_back();  // the channel's NUL
  EXPECT_NE(reasonOf(no_nul).find("NUL"), std::string::npos);
  EXPECT_NE(reasonOf(shortDatagram(1, std::string(64, 'C'), "x")).find("NUL"), std::string::npos)
      << "longer than LCM's 63-character names";
  EXPECT_EQ(parse(shortDatagram(1, std::string(63, 'C'), "x")).kind, Packet::Kind::Short);

  auto parts = fragments(9, "BIG", patterned(100, 2), 40);
  Bytes bad_index = parts[1];
  bad_index[17] = 9;  // fragment 9 of 3
  EXPECT_NE(reasonOf(bad_index).find("out of range"), std::string::npos);
  Bytes no_count = parts[1];
  no_count[18] = no_count[19] = 0;
  EXPECT_NE(reasonOf(no_count).find("out of range"), std::string::npos);
  Bytes past_end = parts[2];
  past_end[15] = 90;  // offset 90 of a 100-byte message, with more than 10 bytes
  EXPECT_NE(reasonOf(past_end).find("past the end"), std::string::npos);
  Bytes huge = parts[1];
  huge[8] = 0x7f;  // a message of 2 GB
  EXPECT_NE(reasonOf(huge).find("larger"), std::string::npos);
  EXPECT_NE(reasonOf(Bytes(parts[1].begin(), parts[1].begin() + 12)).find("fragment header"), std::string::npos);
}

TEST(LcmWire, AssemblesFragmentsInAnyOrder) {
  const std::string payload = patterned(250000, 3);
  auto parts = fragments(40, "CAMERA_DEPTH", payload, 65487);
  ASSERT_EQ(parts.size(), 4u);
  std::mt19937 random(11);
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(parts.begin(), parts.end(), random);
    FragmentAssembler assembler;
    Message message;
    int completed = 0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const bool done = assembler.add(1, parse(parts[i]), 1000 + static_cast<int64_t>(i), message);
      EXPECT_EQ(done, i + 1 == parts.size()) << "fragment " << i;
      completed += done ? 1 : 0;
    }
    ASSERT_EQ(completed, 1);
    EXPECT_EQ(message.channel, "CAMERA_DEPTH");
    EXPECT_EQ(asString(message), payload);
    EXPECT_EQ(message.recv_utime, 1003) << "the receive time of its last datagram";
    EXPECT_EQ(assembler.partialMessages(), 0u);
  }
}

TEST(LcmWire, KeepsSendersAndSequenceNumbersApart) {
  const std::string a = patterned(5000, 4), b = patterned(7000, 5);
  const auto from_a = fragments(1, "A", a, 1500), from_b = fragments(1, "B", b, 1500);
  FragmentAssembler assembler;
  Message message;
  std::vector<std::string> done;
  for (std::size_t i = 0; i < std::max(from_a.size(), from_b.size()); ++i) {
    // The same sequence number from two senders, interleaved.
    if (i < from_a.size() && assembler.add(100, parse(from_a[i]), 0, message)) done.push_back(asString(message));
    if (i < from_b.size() && assembler.add(200, parse(from_b[i]), 0, message)) done.push_back(asString(message));
  }
  ASSERT_EQ(done.size(), 2u);
  EXPECT_EQ(done[0], a);
  EXPECT_EQ(done[1], b);
}

TEST(LcmWire, DuplicatesAreIgnoredAndUnfinishedMessagesDroppedOldestFirst) {
  FragmentAssembler assembler(3);
  Message message;
  const auto parts = fragments(1, "M", patterned(3000, 6), 1200);
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_FALSE(assembler.add(1, parse(parts[0]), 0, message));
  EXPECT_FALSE(assembler.add(1, parse(parts[0]), 0, message)) << "a duplicate does not count twice";
  EXPECT_FALSE(assembler.add(1, parse(parts[1]), 0, message));
  EXPECT_EQ(assembler.rejectedFragments(), 1u);
  // Three other messages begin and none ends: the first is dropped to make room.
  for (uint32_t sequence = 2; sequence <= 4; ++sequence)
    EXPECT_FALSE(assembler.add(1, parse(fragments(sequence, "M", patterned(3000, 6), 1200)[0]), 0, message));
  EXPECT_EQ(assembler.partialMessages(), 3u);
  EXPECT_EQ(assembler.droppedIncomplete(), 1u);
  EXPECT_FALSE(assembler.add(1, parse(parts[2]), 0, message))
      << "the last fragment of a dropped message opens a new, unfinished one";
  // A reused sequence number with another size replaces the unfinished message.
  EXPECT_EQ(assembler.droppedIncomplete(), 2u);
  const auto other = fragments(3, "M", patterned(2000, 7), 1200);
  int completed = 0;
  for (const auto& part : other) {
    if (!assembler.add(1, parse(part), 0, message)) continue;
    ++completed;
    EXPECT_EQ(asString(message), patterned(2000, 7));
  }
  EXPECT_EQ(completed, 1);
  EXPECT_EQ(assembler.droppedIncomplete(), 3u);
}

}  // namespace

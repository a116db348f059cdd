// The run's key: how a key file is read, what the tag covers, and that a
// keyed receiver refuses (and counts) a message without a valid tag.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lib/common/channels.hpp"
#include "lib/transport/message_key.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/transport/transport.hpp"
#include "lib/wire/envelope.hpp"
#include "lib/wire/reject_counter.hpp"

using beft::transport::MessageKey;

namespace {

class KeyFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (std::filesystem::temp_directory_path() / "beft_key_test_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }

  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  std::string dir_;
};

std::string rawBytes(std::size_t count, uint8_t first = 1) {
  std::string bytes;
  for (std::size_t i = 0; i < count; ++i) bytes.push_back(static_cast<char>(first + i * 7));
  return bytes;
}

std::string hexOf(const std::string& bytes) {
  std::string hex;
  char digits[3];
  for (unsigned char byte : bytes) {
    std::snprintf(digits, sizeof digits, "%02x", byte);
    hex += digits;
  }
  return hex;
}

MessageKey keyOf(uint8_t fill) {
  std::array<uint8_t, MessageKey::kBytes> bytes{};
  bytes.fill(fill);
  return MessageKey(bytes);
}

const std::vector<uint8_t> kPayload = {1, 2, 3, 4, 5, 6, 7, 8, 9};

}  // namespace

TEST_F(KeyFiles, RawBytesAndTheirHexTextAreTheSameKey) {
  const std::string bytes = rawBytes(32);
  std::string why;
  const auto raw = MessageKey::fromFile(write("raw.key", bytes), &why);
  ASSERT_TRUE(raw) << why;
  // Hex text as `beft key new` writes it, whitespace and a newline allowed.
  const std::string hex = hexOf(bytes);
  const auto text = MessageKey::fromFile(write("hex.key", hex.substr(0, 20) + " \n" + hex.substr(20) + "\n"), &why);
  ASSERT_TRUE(text) << why;
  EXPECT_EQ(raw->bytes(), text->bytes());
  const auto other = MessageKey::fromFile(write("other.key", rawBytes(32, 2)), &why);
  ASSERT_TRUE(other);
  EXPECT_NE(raw->bytes(), other->bytes());
}

TEST_F(KeyFiles, ALongerKeyCountsEveryByte) {
  std::string why;
  const auto first = MessageKey::fromFile(write("a.key", rawBytes(48) + "a"), &why);
  const auto second = MessageKey::fromFile(write("b.key", rawBytes(48) + "b"), &why);
  ASSERT_TRUE(first && second) << why;
  EXPECT_NE(first->bytes(), second->bytes());
}

TEST_F(KeyFiles, TooShortIsRefusedWithTheReason) {
  std::string why;
  EXPECT_FALSE(MessageKey::fromFile(write("short.key", rawBytes(31)), &why));
  EXPECT_NE(why.find("at least 32 bytes"), std::string::npos) << why;
  why.clear();
  EXPECT_FALSE(MessageKey::fromFile(write("short_hex.key", hexOf(rawBytes(31)) + "\n"), &why));
  EXPECT_NE(why.find("short_hex.key"), std::string::npos) << why;
  EXPECT_FALSE(MessageKey::fromFile(write("empty.key", ""), &why));
}

TEST_F(KeyFiles, AnUnreadableFileIsRefusedWithItsName) {
  std::string why;
  const std::string missing = dir_ + "/no_such.key";
  EXPECT_FALSE(MessageKey::fromFile(missing, &why));
  EXPECT_NE(why.find(missing), std::string::npos) << why;
  if (geteuid() != 0) {  // root reads any file
    const std::string locked = write("locked.key", rawBytes(32));
    chmod(locked.c_str(), 0);
    why.clear();
    EXPECT_FALSE(MessageKey::fromFile(locked, &why));
    EXPECT_NE(why.find("cannot read"), std::string::npos) << why;
  }
}

TEST(MessageKey, RandomKeysDiffer) { EXPECT_NE(MessageKey::random().bytes(), MessageKey::random().bytes()); }

TEST(MessageTag, ChangesWithChannelSenderSequencePayloadAndKey) {
  const MessageKey key = keyOf(0x11);
  const auto tag = beft::transport::tagOf(key, "FIRE@1", 5, 9, kPayload.data(), kPayload.size());
  EXPECT_EQ(tag, beft::transport::tagOf(key, "FIRE@1", 5, 9, kPayload.data(), kPayload.size()));
  EXPECT_NE(tag, beft::transport::tagOf(key, "FIRE@2", 5, 9, kPayload.data(), kPayload.size()));
  EXPECT_NE(tag, beft::transport::tagOf(key, "DONE@1", 5, 9, kPayload.data(), kPayload.size()));
  EXPECT_NE(tag, beft::transport::tagOf(key, "FIRE@1", 6, 9, kPayload.data(), kPayload.size()));
  EXPECT_NE(tag, beft::transport::tagOf(key, "FIRE@1", 5, 10, kPayload.data(), kPayload.size()));
  std::vector<uint8_t> changed = kPayload;
  changed.back() ^= 1;
  EXPECT_NE(tag, beft::transport::tagOf(key, "FIRE@1", 5, 9, changed.data(), changed.size()));
  EXPECT_NE(tag, beft::transport::tagOf(key, "FIRE@1", 5, 9, kPayload.data(), kPayload.size() - 1));
  EXPECT_NE(tag, beft::transport::tagOf(keyOf(0x12), "FIRE@1", 5, 9, kPayload.data(), kPayload.size()));
}

TEST(MessageTag, ValidOnlyForTheTaggedMessageUnderItsKey) {
  const MessageKey key = keyOf(0x21);
  beft::wire::Envelope envelope;
  envelope.sender = 77;
  envelope.sequence = 3;
  envelope.tagged = true;
  envelope.tag = beft::transport::tagOf(key, "VISION", 77, 3, kPayload.data(), kPayload.size());
  EXPECT_TRUE(beft::transport::tagValid(key, "VISION", envelope, kPayload.data(), kPayload.size()));

  std::vector<uint8_t> changed = kPayload;
  changed[0] ^= 0x80;
  EXPECT_FALSE(beft::transport::tagValid(key, "VISION", envelope, changed.data(), changed.size()));
  EXPECT_FALSE(beft::transport::tagValid(key, "AUDIO", envelope, kPayload.data(), kPayload.size()));
  EXPECT_FALSE(beft::transport::tagValid(keyOf(0x22), "VISION", envelope, kPayload.data(), kPayload.size()));
  beft::wire::Envelope renumbered = envelope;
  renumbered.sequence = 4;
  EXPECT_FALSE(beft::transport::tagValid(key, "VISION", renumbered, kPayload.data(), kPayload.size()));

  beft::wire::Envelope untagged = envelope;
  untagged.tagged = false;  // the tag bytes are still there, but the envelope says it has none
  EXPECT_FALSE(beft::transport::tagValid(key, "VISION", untagged, kPayload.data(), kPayload.size()));
}

namespace {

// The payload with an envelope from `sender`, tagged with `key` when given.
std::vector<uint8_t> enveloped(const std::string& channel, uint64_t sender, const MessageKey* key) {
  std::vector<uint8_t> bytes = kPayload;
  beft::wire::Envelope envelope;
  envelope.sender = sender;
  envelope.sequence = 1;
  envelope.tagged = key != nullptr;
  if (key) envelope.tag = beft::transport::tagOf(*key, channel, sender, 1, kPayload.data(), kPayload.size());
  beft::wire::appendEnvelope(bytes, envelope);
  return bytes;
}

}  // namespace

// On memq:// (LCM's own receive path): a message published with the run's
// key passes; the same message without an envelope (a replayed log), with
// an envelope but no tag, or tagged with another key is refused and
// counted, per receiver and in the process's reject counter.
TEST(KeyedReceiver, RefusesAndCountsWhatLacksAValidTag) {
  lcm::LCM lcm("memq://");
  ASSERT_TRUE(lcm.good());
  const std::string channel = beft::channels::kTaskCommand.name;
  const MessageKey key = keyOf(0x31), other = keyOf(0x32);
  beft::transport::setProcessKey(key);  // before the receiver: it takes the key when it opens
  beft::transport::Selection selection;
  selection.rules = {beft::transport::channelRule(channel)};
  auto receiver = beft::transport::openReceiver(lcm, "memq://", selection);
  const uint64_t refused_before = beft::wire::processRejects().totalOf(beft::wire::Fault::kUnauthenticated);

  beft::transport::publishEncoded(lcm, channel, kPayload.data(), kPayload.size());  // tagged with the key
  lcm.publish(channel, kPayload.data(), static_cast<unsigned>(kPayload.size()));
  for (const auto& bytes : {enveloped(channel, 98, nullptr), enveloped(channel, 99, &other)})
    lcm.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));

  std::vector<std::vector<uint8_t>> taken;
  receiver->receive(100, [&](const beft::transport::Message& message) {
    taken.emplace_back(message.data, message.data + message.size);
  });
  EXPECT_EQ(receiver->repairStats().unauthenticated, 3u);
  receiver.reset();
  beft::transport::setProcessKey(std::nullopt);
  ASSERT_EQ(taken.size(), 1u);
  EXPECT_EQ(taken[0], kPayload);  // the envelope came off
  EXPECT_EQ(beft::wire::processRejects().totalOf(beft::wire::Fault::kUnauthenticated), refused_before + 3);
}

#include "lib/transport/message_key.hpp"

#include <sodium.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <mutex>
#include <vector>

#include "lib/common/log.hpp"

namespace beft::transport {

namespace {

void initSodium() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (sodium_init() < 0) {
      std::fprintf(stderr, "libsodium cannot start\n");
      std::abort();
    }
  });
}

// The key file's bytes as a key: raw bytes, or hexadecimal text (whitespace ignored).
std::optional<std::array<uint8_t, MessageKey::kBytes>> keyBytes(const std::vector<uint8_t>& content) {
  std::string hex;
  bool all_hex = !content.empty();
  for (uint8_t byte : content) {
    if (std::isspace(byte)) continue;
    if (!std::isxdigit(byte)) {
      all_hex = false;
      break;
    }
    hex.push_back(static_cast<char>(byte));
  }
  std::vector<uint8_t> bytes;
  if (all_hex && hex.size() % 2 == 0) {
    for (std::size_t i = 0; i < hex.size(); i += 2)
      bytes.push_back(static_cast<uint8_t>(std::stoi(hex.substr(i, 2), nullptr, 16)));
  } else {
    bytes = content;
  }
  if (bytes.size() < MessageKey::kBytes) return std::nullopt;
  // A longer key is folded to 32 bytes by a hash, so every byte counts.
  std::array<uint8_t, MessageKey::kBytes> key{};
  initSodium();
  crypto_generichash(key.data(), key.size(), bytes.data(), bytes.size(), nullptr, 0);
  return key;
}

struct ProcessKey {
  std::mutex mutex;
  bool loaded = false;
  std::optional<MessageKey> key;
};

ProcessKey& processKeyState() {
  static ProcessKey state;
  return state;
}

}  // namespace

std::optional<MessageKey> MessageKey::fromFile(const std::string& path, std::string* why) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    if (why) *why = "cannot read the key file " + path;
    return std::nullopt;
  }
  const std::vector<uint8_t> content((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const auto bytes = keyBytes(content);
  if (!bytes) {
    if (why) *why = path + ": a key needs at least 32 bytes (or 64 hexadecimal digits)";
    return std::nullopt;
  }
  return MessageKey(*bytes);
}

MessageKey MessageKey::random() {
  initSodium();
  std::array<uint8_t, kBytes> bytes{};
  randombytes_buf(bytes.data(), bytes.size());
  return MessageKey(bytes);
}

const MessageKey* processKey() {
  ProcessKey& state = processKeyState();
  std::lock_guard<std::mutex> lock(state.mutex);
  if (!state.loaded) {
    state.loaded = true;
    const char* path = std::getenv("BEFT_KEY_FILE");
    if (path != nullptr && *path != '\0') {
      std::string why;
      state.key = MessageKey::fromFile(path, &why);
      if (!state.key) {
        std::fprintf(stderr, "BEFT_KEY_FILE: %s; a keyed run does not run without its key\n", why.c_str());
        std::exit(2);
      }
    }
  }
  return state.key ? &*state.key : nullptr;
}

void setProcessKey(std::optional<MessageKey> key) {
  ProcessKey& state = processKeyState();
  std::lock_guard<std::mutex> lock(state.mutex);
  state.loaded = true;
  state.key = std::move(key);
}

std::array<uint8_t, wire::kTagBytes> tagOf(const MessageKey& key, std::string_view channel, uint64_t sender,
                                           uint64_t sequence, const uint8_t* payload, std::size_t size) {
  initSodium();
  crypto_generichash_state hash;
  crypto_generichash_init(&hash, key.bytes().data(), key.bytes().size(), wire::kTagBytes);
  const uint8_t separator = 0;
  crypto_generichash_update(&hash, reinterpret_cast<const uint8_t*>(channel.data()), channel.size());
  crypto_generichash_update(&hash, &separator, 1);
  uint8_t numbers[16];
  for (int i = 0; i < 8; ++i) {
    numbers[i] = static_cast<uint8_t>(sender >> (56 - 8 * i));
    numbers[8 + i] = static_cast<uint8_t>(sequence >> (56 - 8 * i));
  }
  crypto_generichash_update(&hash, numbers, sizeof numbers);
  crypto_generichash_update(&hash, payload, size);
  std::array<uint8_t, wire::kTagBytes> tag{};
  crypto_generichash_final(&hash, tag.data(), tag.size());
  return tag;
}

bool tagValid(const MessageKey& key, std::string_view channel, const wire::Envelope& envelope, const uint8_t* payload,
              std::size_t size) {
  if (!envelope.tagged) return false;
  const auto expected = tagOf(key, channel, envelope.sender, envelope.sequence, payload, size);
  return sodium_memcmp(expected.data(), envelope.tag.data(), expected.size()) == 0;
}

}  // namespace beft::transport

#include "lib/transport/detail/udpm_filter.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <lcm/lcm-cpp.hpp>

#include "lib/common/log.hpp"
#include "lib/transport/detail/udpm_receiver.hpp"

namespace beft::udpm_filter {

namespace {

// Offsets in the datagram as a UDP socket's filter sees it: the UDP header
// (8 bytes) first, then LCM's header: magic, sequence number, channel.
constexpr uint32_t kUdpHeaderBytes = 8;
constexpr uint32_t kMagicOffset = kUdpHeaderBytes;
constexpr uint32_t kChannelOffset = kUdpHeaderBytes + 8;
constexpr uint32_t kFingerprintBytes = 8;
constexpr uint32_t kMagicShort = 0x4c433032;     // "LC02": the whole message in one datagram
constexpr uint32_t kMagicFragment = 0x4c433033;  // "LC03": one fragment of a large message
constexpr uint32_t kAccept = 0xffffffffu;        // keep the whole datagram
constexpr uint32_t kReject = 0;

struct Pattern {
  uint32_t offset;
  std::string bytes;
};

uint32_t bigEndian(const std::string& bytes, std::size_t at, std::size_t count) {
  uint32_t value = 0;
  for (std::size_t i = 0; i < count; ++i) value = (value << 8) | static_cast<uint8_t>(bytes[at + i]);
  return value;
}

// One rule: the length check, one load and compare per chunk, the verdict.
std::vector<sock_filter> compileRule(const std::vector<Pattern>& patterns, uint32_t verdict) {
  struct Load {
    uint16_t size;
    uint32_t offset, value;
  };
  std::vector<Load> loads;
  uint32_t end = 0;
  for (const auto& pattern : patterns) {
    std::size_t i = 0;
    while (i < pattern.bytes.size()) {
      const std::size_t left = pattern.bytes.size() - i;
      const std::size_t count = left >= 4 ? 4 : left >= 2 ? 2 : 1;
      const uint16_t size = count == 4 ? BPF_W : count == 2 ? BPF_H : BPF_B;
      loads.push_back({size, static_cast<uint32_t>(pattern.offset + i), bigEndian(pattern.bytes, i, count)});
      i += count;
    }
    end = std::max<uint32_t>(end, pattern.offset + static_cast<uint32_t>(pattern.bytes.size()));
  }
  const std::size_t length = 2 + 2 * loads.size() + 1;
  if (length > 255) throw std::invalid_argument("udpm filter: a rule of " + std::to_string(end) + " bytes is too long");
  // A jump at index i skips jf instructions: jf = length - (i + 1) lands on the
  // first instruction after this rule, i.e. the next rule.
  std::vector<sock_filter> code;
  code.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_LEN, 0));
  code.push_back(BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, end, 0, 0));  // too short for this rule
  code.back().jf = static_cast<uint8_t>(length - code.size());
  for (const auto& load : loads) {
    code.push_back(BPF_STMT(BPF_LD | load.size | BPF_ABS, load.offset));
    code.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, load.value, 0, 0));
    code.back().jf = static_cast<uint8_t>(length - code.size());
  }
  code.push_back(BPF_STMT(BPF_RET | BPF_K, verdict));
  return code;
}

}  // namespace

}  // namespace beft::udpm_filter

namespace beft::transport {

Rule channelRule(const std::string& channel) {
  Rule rule;
  rule.channel = channel;
  return rule;
}

bool isPlainChannel(const std::string& pattern) {
  if (pattern.empty()) return false;
  for (char c : pattern)
    if (std::string_view("\\^$.|?*+()[]{}").find(c) != std::string_view::npos) return false;
  return true;
}

int udpmPort(const std::string& url) {
  const auto endpoint = udpm::parseUrl(url);
  return endpoint ? endpoint->port : -1;
}

}  // namespace beft::transport

namespace beft::udpm_filter {

std::vector<sock_filter> compile(const Spec& spec) {
  const bool accept_listed = spec.mode == Spec::Mode::AcceptListed;
  std::vector<sock_filter> code;
  code.push_back(BPF_STMT(BPF_LD | BPF_W | BPF_ABS, kMagicOffset));
  code.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, kMagicFragment, 0, 1));
  code.push_back(BPF_STMT(BPF_RET | BPF_K, kAccept));
  code.push_back(BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, kMagicShort, 1, 0));
  code.push_back(BPF_STMT(BPF_RET | BPF_K, kReject));  // not an LCM datagram
  for (const auto& rule : spec.rules) {
    if (rule.channel.empty()) throw std::invalid_argument("udpm filter: a rule without a channel");
    std::vector<Pattern> patterns{{kChannelOffset, rule.channel + '\0'}};
    if (!rule.field.empty()) {
      const auto data_offset = kChannelOffset + static_cast<uint32_t>(rule.channel.size() + 1);
      patterns.push_back({data_offset + kFingerprintBytes + static_cast<uint32_t>(rule.field_offset), rule.field});
    }
    const auto rule_code = compileRule(patterns, accept_listed ? kAccept : kReject);
    code.insert(code.end(), rule_code.begin(), rule_code.end());
  }
  code.push_back(BPF_STMT(BPF_RET | BPF_K, accept_listed ? kReject : kAccept));
  if (code.size() > BPF_MAXINSNS) throw std::invalid_argument("udpm filter: too many rules");
  return code;
}

bool accepts(const Spec& spec, std::string_view channel, const void* data, std::size_t size) {
  const bool accept_listed = spec.mode == Spec::Mode::AcceptListed;
  const auto* bytes = static_cast<const char*>(data);
  for (const auto& rule : spec.rules) {
    if (channel != rule.channel) continue;
    if (!rule.field.empty()) {
      const std::size_t at = kFingerprintBytes + rule.field_offset;
      if (size < at + rule.field.size() || std::string_view(bytes + at, rule.field.size()) != rule.field) continue;
    }
    return accept_listed;
  }
  return !accept_listed;
}

bool attach(int fd, const Spec& spec) {
  auto code = compile(spec);
  sock_fprog program{static_cast<unsigned short>(code.size()), code.data()};
  return setsockopt(fd, SOL_SOCKET, SO_ATTACH_FILTER, &program, sizeof(program)) == 0;
}

int findReceiveSocket(int port) {
  int found = -1, count = 0;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator("/proc/self/fd", error)) {
    int fd = -1;
    try {
      fd = std::stoi(entry.path().filename().string());
    } catch (const std::exception&) {
      continue;
    }
    int type = 0;
    socklen_t type_size = sizeof(type);
    if (getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &type_size) != 0 || type != SOCK_DGRAM) continue;
    sockaddr_in address{};
    socklen_t address_size = sizeof(address);
    if (getsockname(fd, reinterpret_cast<sockaddr*>(&address), &address_size) != 0) continue;
    if (address.sin_family != AF_INET || ntohs(address.sin_port) != port) continue;
    found = fd;
    ++count;
  }
  return count == 1 ? found : -1;
}

bool install(lcm::LCM& lcm, const std::string& url, const Spec& spec, std::string* why) {
  auto fail = [why](std::string reason) {
    if (why) *why = std::move(reason);
    return false;
  };
  if (const char* setting = std::getenv("BEFT_UDPM_FILTER"); setting && std::string(setting) == "0")
    return fail("turned off by BEFT_UDPM_FILTER=0");
  const int port = udpmPort(url);
  if (port < 0) return fail("not a udpm:// URL");
  // LCM opens its receive socket with the first subscription or this call.
  if (lcm_get_fileno(lcm.getUnderlyingLCM()) < 0) return fail("LCM has no receive socket");
  const int fd = findReceiveSocket(port);
  if (fd < 0) return fail("no single UDP socket bound to port " + std::to_string(port));
  if (!attach(fd, spec)) return fail("SO_ATTACH_FILTER failed");
  return true;
}

std::string describe(const Spec& spec) {
  std::string listed, previous;
  for (const auto& rule : spec.rules) {
    const std::string item = rule.channel + (rule.what.empty() ? "" : " (" + rule.what + ")");
    if (item != previous) listed += (listed.empty() ? "" : ", ") + item;
    previous = item;
  }
  return (spec.mode == Spec::Mode::AcceptListed ? "receiving only " : "dropping ") +
         (listed.empty() ? std::string("nothing") : listed);
}

bool installAndReport(lcm::LCM& lcm, const std::string& url, const Spec& spec) {
  std::string why;
  if (!install(lcm, url, spec, &why)) {
    log::info("every channel reaches this process (no kernel filter: ", why, ")");
    return false;
  }
  log::info("kernel filter: ", describe(spec));
  return true;
}

}  // namespace beft::udpm_filter

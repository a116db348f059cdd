#include "lib/transport/detail/udpm_receiver.hpp"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace beft::udpm {

namespace {

constexpr std::size_t kDatagramBuffer = lcm_wire::kLargestDatagram + 1;
// SO_TIMESTAMP and SO_RXQ_OVFL, with room to spare.
constexpr std::size_t kControlBytes = CMSG_SPACE(sizeof(timeval)) + CMSG_SPACE(sizeof(uint32_t)) + 64;

bool fail(std::string* why, std::string reason) {
  if (why) *why = std::move(reason);
  return false;
}

bool parseInt(const std::string& text, int& value) {
  if (text.empty()) return false;
  try {
    std::size_t used = 0;
    const long parsed = std::stol(text, &used, 0);
    if (used != text.size() || parsed < 0 || parsed > 0x7fffffff) return false;
    value = static_cast<int>(parsed);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

[[noreturn]] void throwErrno(const std::string& step) {
  throw std::runtime_error("udpm receiver: " + step + ": " + std::strerror(errno));
}

}  // namespace

std::optional<Endpoint> parseUrl(const std::string& url, std::string* why) {
  const std::string scheme = "udpm://";
  if (url.rfind(scheme, 0) != 0) {
    fail(why, "not a udpm:// URL");
    return std::nullopt;
  }
  Endpoint endpoint;
  const auto query_at = url.find('?', scheme.size());
  const std::string address = url.substr(scheme.size(), query_at - scheme.size());
  const auto colon = address.find(':');
  if (!address.empty()) endpoint.group = address.substr(0, colon);
  in_addr group{};
  if (inet_aton(endpoint.group.c_str(), &group) == 0 || !IN_MULTICAST(ntohl(group.s_addr))) {
    fail(why, "'" + endpoint.group + "' is not a multicast address");
    return std::nullopt;
  }
  if (colon != std::string::npos &&
      (!parseInt(address.substr(colon + 1), endpoint.port) || endpoint.port > 65535)) {
    fail(why, "bad port in " + url);
    return std::nullopt;
  }
  if (query_at == std::string::npos) return endpoint;
  std::size_t at = query_at + 1;
  while (at <= url.size()) {
    const auto amp = url.find('&', at);
    const std::string item = url.substr(at, amp == std::string::npos ? std::string::npos : amp - at);
    const auto equals = item.find('=');
    const std::string key = item.substr(0, equals);
    const std::string value = equals == std::string::npos ? "" : item.substr(equals + 1);
    if (key == "ttl" && !parseInt(value, endpoint.ttl)) {
      fail(why, "bad ttl in " + url);
      return std::nullopt;
    }
    if (key == "recv_buf_size" && !parseInt(value, endpoint.recv_buf_size)) {
      fail(why, "bad recv_buf_size in " + url);
      return std::nullopt;
    }
    if (amp == std::string::npos) break;
    at = amp + 1;
  }
  return endpoint;
}

Receiver::Receiver(const Endpoint& endpoint, udpm_filter::Spec spec, std::size_t batch)
    : spec_(std::move(spec)), batch_(batch == 0 ? 1 : batch) {
  in_addr group{};
  if (inet_aton(endpoint.group.c_str(), &group) == 0)
    throw std::runtime_error("udpm receiver: bad group address " + endpoint.group);
  fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throwErrno("socket");
  try {
    const int on = 1;
    // Every process of the run binds the same port (as LCM's own sockets do).
    if (setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on) != 0) throwErrno("SO_REUSEADDR");
    if (endpoint.recv_buf_size > 0) {
      if (setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &endpoint.recv_buf_size, sizeof endpoint.recv_buf_size) != 0)
        throwErrno("SO_RCVBUF");
      // The kernel caps SO_RCVBUF at net.core.rmem_max (208 KiB unless
      // raised); a process allowed to (root) takes the size asked for anyway.
      if (receiveBufferBytes() < endpoint.recv_buf_size)
        setsockopt(fd_, SOL_SOCKET, SO_RCVBUFFORCE, &endpoint.recv_buf_size, sizeof endpoint.recv_buf_size);
    }
    // The kernel's receive time, as LCM takes it (log timestamps stay exact
    // when datagrams are read in batches).
    if (setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMP, &on, sizeof on) != 0) throwErrno("SO_TIMESTAMP");
    if (countsLosses()) {
      // The kernel's count of datagrams dropped on this socket. It also
      // counts what a filter drops, so only an unfiltered socket has it.
      if (setsockopt(fd_, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof on) != 0) throwErrno("SO_RXQ_OVFL");
    } else if (!udpm_filter::attach(fd_, spec_)) {
      // The filter before the bind: nothing it drops is ever queued.
      throwErrno("SO_ATTACH_FILTER");
    }
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr = group;
    address.sin_port = htons(static_cast<uint16_t>(endpoint.port));
    if (bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0)
      throwErrno("bind to " + endpoint.group + ":" + std::to_string(endpoint.port));
    ip_mreq membership{};
    membership.imr_multiaddr = group;
    membership.imr_interface.s_addr = htonl(INADDR_ANY);
    if (setsockopt(fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof membership) != 0)
      throwErrno("joining " + endpoint.group);
  } catch (...) {
    close(fd_);
    throw;
  }
  buffers_.resize(batch_ * kDatagramBuffer);
  controls_.resize(batch_ * kControlBytes);
  sources_.resize(batch_);
  headers_.resize(batch_);
  vectors_.resize(batch_);
}

Receiver::~Receiver() {
  if (fd_ >= 0) close(fd_);
}

int Receiver::drain(const MessageHandler& handler) {
  const uint64_t messages_before = stats_.messages;
  for (;;) {
    for (std::size_t i = 0; i < batch_; ++i) {
      vectors_[i] = {buffers_.data() + i * kDatagramBuffer, kDatagramBuffer - 1};
      msghdr& header = headers_[i].msg_hdr;
      header = {};
      header.msg_name = &sources_[i];
      header.msg_namelen = sizeof(sockaddr_in);
      header.msg_iov = &vectors_[i];
      header.msg_iovlen = 1;
      header.msg_control = controls_.data() + i * kControlBytes;
      header.msg_controllen = kControlBytes;
    }
    const int count = recvmmsg(fd_, headers_.data(), static_cast<unsigned>(batch_), MSG_DONTWAIT, nullptr);
    if (count < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK) break;
      if (errno == EINTR) continue;
      return -1;
    }
    for (int i = 0; i < count; ++i) handleDatagram(static_cast<std::size_t>(i), headers_[i].msg_len, handler);
    if (static_cast<std::size_t>(count) < batch_) break;  // the queue is empty
  }
  return static_cast<int>(stats_.messages - messages_before);
}

int Receiver::receive(int timeout_ms, const MessageHandler& handler) {
  if (!waitReadable({fd_}, timeout_ms)) return 0;
  return drain(handler);
}

void Receiver::handleDatagram(std::size_t index, std::size_t size, const MessageHandler& handler) {
  ++stats_.datagrams;
  msghdr& header = headers_[index].msg_hdr;
  int64_t recv_utime = 0;
  for (cmsghdr* control = CMSG_FIRSTHDR(&header); control; control = CMSG_NXTHDR(&header, control)) {
    if (control->cmsg_level != SOL_SOCKET) continue;
    if (control->cmsg_type == SCM_TIMESTAMP) {
      timeval when{};
      std::memcpy(&when, CMSG_DATA(control), sizeof when);
      recv_utime = int64_t{when.tv_sec} * 1000000 + when.tv_usec;
    } else if (control->cmsg_type == SO_RXQ_OVFL) {
      // The kernel's running count of datagrams dropped on this socket.
      uint32_t dropped = 0;
      std::memcpy(&dropped, CMSG_DATA(control), sizeof dropped);
      if (overflow_seen_) stats_.kernel_dropped += dropped - last_overflow_count_;
      else stats_.kernel_dropped += dropped;
      last_overflow_count_ = dropped;
      overflow_seen_ = true;
    }
  }
  if (recv_utime == 0) {
    timeval now{};
    gettimeofday(&now, nullptr);
    recv_utime = int64_t{now.tv_sec} * 1000000 + now.tv_usec;
  }
  const uint8_t* bytes = buffers_.data() + index * kDatagramBuffer;
  const lcm_wire::Packet packet = lcm_wire::parsePacket(bytes, size);
  lcm_wire::Message message;
  if (packet.kind == lcm_wire::Packet::Kind::Short) {
    // The kernel filter has already checked the channel.
    message.channel = packet.channel;
    message.data = packet.payload;
    message.size = packet.payload_size;
    message.recv_utime = recv_utime;
  } else if (packet.kind == lcm_wire::Packet::Kind::Fragment) {
    const sockaddr_in& source = sources_[index];
    const uint64_t sender = (uint64_t{source.sin_addr.s_addr} << 16) | source.sin_port;
    if (!assembler_.add(sender, packet, recv_utime, message)) return;
    // Fragments pass the kernel filter unseen: check the whole message here.
    if (!udpm_filter::accepts(spec_, message.channel, message.data, message.size)) return;
  } else {
    ++stats_.invalid;
    return;
  }
  ++stats_.messages;
  handler(message);
}

bool Receiver::countsLosses() const {
  return spec_.mode == udpm_filter::Spec::Mode::RejectListed && spec_.rules.empty();
}

Receiver::Stats Receiver::stats() const {
  Stats stats = stats_;
  stats.incomplete = assembler_.droppedIncomplete();
  return stats;
}

int Receiver::receiveBufferBytes() const {
  int size = 0;
  socklen_t length = sizeof size;
  getsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &size, &length);
  return size;
}

bool waitReadable(std::initializer_list<int> fds, int timeout_ms) {
  std::array<pollfd, 4> polled{};
  if (fds.size() > polled.size()) throw std::invalid_argument("waitReadable: more than four sockets");
  std::size_t count = 0;
  for (int fd : fds) polled[count++] = {fd, POLLIN, 0};  // poll leaves out a negative fd
  return poll(polled.data(), count, timeout_ms) > 0;
}

}  // namespace beft::udpm

#include "services/ssr_bridge/ssr_link.hpp"

#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "lib/common/log.hpp"

namespace beft::ssr_bridge {

namespace {

constexpr auto kRetryPeriod = std::chrono::seconds(1);
// SSR reads every request at once; this much unread means it has stalled.
constexpr std::size_t kMostQueuedBytes = 4 << 20;
constexpr std::size_t kReadChunk = 64 << 10;
constexpr std::size_t kMostReadPerTurn = 1 << 20;  // then the caller gets a turn

}  // namespace

SsrLink::SsrLink(std::string host, int port) : host_(std::move(host)), port_(port) {}

SsrLink::~SsrLink() {
  if (fd_ >= 0) close(fd_);
  if (addresses_) freeaddrinfo(addresses_);
}

short SsrLink::events() const {
  if (state_ == State::Connecting) return POLLOUT;
  if (state_ == State::Connected) return static_cast<short>(POLLIN | (outgoing_.empty() ? 0 : POLLOUT));
  return 0;
}

int SsrLink::millisecondsUntilAttempt() const {
  if (state_ != State::Waiting) return -1;
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(next_attempt_ - Clock::now()).count();
  return left > 0 ? static_cast<int>(left) : 0;
}

void SsrLink::fail(const std::string& why) {
  const bool was_connected = state_ == State::Connected;
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
  if (addresses_) freeaddrinfo(addresses_);
  addresses_ = next_address_ = nullptr;
  outgoing_.clear();
  splitter_ = MessageSplitter();
  state_ = State::Waiting;
  next_attempt_ = Clock::now() + kRetryPeriod;
  if (was_connected) {
    log::warn("lost the connection to SSR at ", address(), " (", why, "); trying again every second");
    outage_reported_ = true;
  } else if (!outage_reported_) {
    log::warn("SSR is not reachable at ", address(), " (", why, "); trying again every second");
    outage_reported_ = true;
  }
}

void SsrLink::startAttempt() {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  const std::string port = std::to_string(port_);
  const int code = getaddrinfo(host_.c_str(), port.c_str(), &hints, &addresses_);
  if (code != 0) {
    addresses_ = nullptr;
    fail(std::string("cannot resolve the host: ") + gai_strerror(code));
    return;
  }
  next_address_ = addresses_;
  last_error_ = "no address";
  if (!connectNextAddress()) fail(last_error_);
}

// localhost may be ::1 first while SSR listens on IPv4 only: each address in turn.
bool SsrLink::connectNextAddress() {
  while (next_address_) {
    const addrinfo* address = next_address_;
    next_address_ = next_address_->ai_next;
    fd_ = socket(address->ai_family, address->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, address->ai_protocol);
    if (fd_ < 0) {
      last_error_ = std::strerror(errno);
      continue;
    }
    const int one = 1;
    setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);  // small requests, sent as they come
    if (connect(fd_, address->ai_addr, address->ai_addrlen) == 0 || errno == EINPROGRESS) {
      state_ = State::Connecting;
      return true;
    }
    last_error_ = std::strerror(errno);
    close(fd_);
    fd_ = -1;
  }
  return false;
}

SsrLink::Event SsrLink::read(std::vector<std::string>& messages) {
  char buffer[kReadChunk];
  std::size_t total = 0;
  while (total < kMostReadPerTurn) {
    const ssize_t n = recv(fd_, buffer, sizeof buffer, 0);
    if (n > 0) {
      splitter_.feed(buffer, static_cast<std::size_t>(n), messages);
      total += static_cast<std::size_t>(n);
      continue;
    }
    if (n == 0) {
      fail("SSR closed it");
      return Event::Lost;
    }
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) break;
    fail(std::strerror(errno));
    return Event::Lost;
  }
  return Event::None;
}

bool SsrLink::write() {
  while (!outgoing_.empty()) {
    const ssize_t n = ::send(fd_, outgoing_.data(), outgoing_.size(), MSG_NOSIGNAL);
    if (n > 0) {
      outgoing_.erase(0, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
    fail(n < 0 ? std::strerror(errno) : "cannot send");
    return false;
  }
  return true;
}

SsrLink::Event SsrLink::service(std::vector<std::string>& messages) {
  if (state_ == State::Waiting) {
    if (Clock::now() < next_attempt_) return Event::None;
    startAttempt();
  }
  if (state_ == State::Connecting) {
    pollfd pfd{fd_, POLLOUT, 0};
    if (poll(&pfd, 1, 0) <= 0) return Event::None;
    int error = 0;
    socklen_t length = sizeof error;
    if (getsockopt(fd_, SOL_SOCKET, SO_ERROR, &error, &length) != 0) error = errno;
    if (error != 0) {
      last_error_ = std::strerror(error);
      close(fd_);
      fd_ = -1;
      if (!connectNextAddress()) fail(last_error_);
      return Event::None;
    }
    freeaddrinfo(addresses_);
    addresses_ = next_address_ = nullptr;
    state_ = State::Connected;
    outage_reported_ = false;
    log::info("connected to SSR at ", address());
    read(messages);
    return state_ == State::Connected ? Event::Connected : Event::Lost;
  }
  if (state_ != State::Connected) return Event::None;
  if (!write()) return Event::Lost;
  return read(messages);
}

void SsrLink::send(const std::string& message) {
  if (state_ != State::Connected) return;
  if (outgoing_.size() + message.size() + 1 > kMostQueuedBytes) {
    fail("SSR has not read " + std::to_string(outgoing_.size()) + " bytes of requests");
    return;
  }
  outgoing_ += message;
  outgoing_ += '\0';
}

bool SsrLink::flush(std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (state_ == State::Connected && !outgoing_.empty()) {
    if (!write()) return false;
    if (outgoing_.empty()) break;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    pollfd pfd{fd_, POLLOUT, 0};
    poll(&pfd, 1, static_cast<int>(left));
  }
  return outgoing_.empty();
}

}  // namespace beft::ssr_bridge

#include "services/bridge/gathered_reads.hpp"

#include <sys/epoll.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "lib/common/log.hpp"

namespace beft::bridge {

GatheredReads::GatheredReads(boost::asio::io_context& io, transport::Receiver& receiver, transport::Handler handler,
                             int batch_ms, std::function<bool()> gather_now)
    : receiver_(receiver),
      handler_(std::move(handler)),
      batch_ms_(batch_ms),
      gather_now_(std::move(gather_now)),
      gather_(io) {
  epoll_fd_ = ::epoll_create1(EPOLL_CLOEXEC);
  if (epoll_fd_ < 0) throw std::runtime_error(std::string("epoll_create1: ") + std::strerror(errno));
  epoll_event event{};
  event.events = EPOLLIN | EPOLLONESHOT;
  if (::epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, receiver_.fd(), &event) != 0) {
    const std::string why = std::strerror(errno);
    ::close(epoll_fd_);
    throw std::runtime_error("epoll_ctl: " + why);
  }
  // asio closes its own copy.
  readable_ = std::make_unique<boost::asio::posix::stream_descriptor>(io, ::dup(epoll_fd_));
}

GatheredReads::~GatheredReads() {
  readable_.reset();
  ::close(epoll_fd_);
}

void GatheredReads::start() { arm(); }

// The wait is queued before the socket is armed: the set becomes readable
// (an edge asio must see) only once asio waits for it.
void GatheredReads::arm() {
  readable_->async_wait(boost::asio::posix::stream_descriptor::wait_read, [this](const boost::system::error_code& e) {
    if (e) return;
    epoll_event taken{};
    (void)::epoll_wait(epoll_fd_, &taken, 1, 0);  // takes the one event: the set is quiet until armed again
    read();
  });
  epoll_event event{};
  event.events = EPOLLIN | EPOLLONESHOT;
  if (::epoll_ctl(epoll_fd_, EPOLL_CTL_MOD, receiver_.fd(), &event) != 0)
    log::warn("cannot watch the run's socket: ", std::strerror(errno));
}

void GatheredReads::read() {
  ++wake_ups_;
  const int handled = receiver_.drain(handler_);
  if (handled < 0) log::warn("receiving failed");
  if (batch_ms_ == 0 || handled <= 0 || handled >= kBurstMessages || !gather_now_()) return arm();
  gather_.expires_after(std::chrono::milliseconds(batch_ms_));
  gather_.async_wait([this](const boost::system::error_code& e) {
    if (!e) arm();
  });
}

}  // namespace beft::bridge

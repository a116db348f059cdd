// Reads a run's receiver on the bridge's io_context in batches: woken by
// the first message, it reads what is there and then lets the next ones
// gather for batch_ms (the kernel queues them, with their receive times)
// before it reads again, unless the read was a burst or gathering is off
// now (an external expert is connected: it is a link of the lockstep chain
// and takes every message as it comes).
//
// Why a descriptor of its own: asio watches a descriptor edge-triggered for
// as long as it holds it, so a socket merely left unread while messages
// gather would still wake the bridge for every datagram. The socket sits in
// an epoll set of this class with EPOLLONESHOT instead: it wakes the
// io_context once per arming, and is armed again only when the gathering is
// over.
#pragma once

#include <functional>
#include <memory>

#include <boost/asio/io_context.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <boost/asio/steady_timer.hpp>

#include "lib/transport/transport.hpp"

namespace beft::bridge {

class GatheredReads {
 public:
  // A read of this many messages is a burst: read on without gathering.
  static constexpr int kBurstMessages = 256;

  // gather_now: whether to gather at this moment (false: read each message as it comes).
  // Throws std::runtime_error when the epoll set cannot be made.
  GatheredReads(boost::asio::io_context& io, transport::Receiver& receiver, transport::Handler handler, int batch_ms,
                std::function<bool()> gather_now);
  ~GatheredReads();
  GatheredReads(const GatheredReads&) = delete;
  GatheredReads& operator=(const GatheredReads&) = delete;

  // Starts waiting for the first message.
  void start();
  uint64_t wakeUps() const { return wake_ups_; }  // reads started, for tests and the log
  int batchMs() const { return batch_ms_; }

 private:
  void arm();
  void read();

  transport::Receiver& receiver_;
  transport::Handler handler_;
  int batch_ms_;
  std::function<bool()> gather_now_;
  int epoll_fd_ = -1;
  std::unique_ptr<boost::asio::posix::stream_descriptor> readable_;  // the epoll set, as asio sees it
  boost::asio::steady_timer gather_;
  uint64_t wake_ups_ = 0;
};

}  // namespace beft::bridge

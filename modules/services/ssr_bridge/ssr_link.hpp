// A TCP connection to SSR's network interface that outlives SSR: while SSR
// is not there it tries again every second, and says so once per outage.
// It never waits, but in flush(): the caller polls fd() for events().
#pragma once

#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include <netdb.h>

#include "services/ssr_bridge/ssr_updates.hpp"

namespace beft::ssr_bridge {

class SsrLink {
 public:
  using Clock = std::chrono::steady_clock;
  SsrLink(std::string host, int port);
  ~SsrLink();
  SsrLink(const SsrLink&) = delete;
  SsrLink& operator=(const SsrLink&) = delete;

  enum class Event { None, Connected, Lost };
  // Does what can be done now: a connection attempt when one is due, the
  // completion of one under way, writing what is queued, reading what SSR
  // sent (its messages appended to `messages`). Connected when a connection
  // was made, Lost when one ended.
  Event service(std::vector<std::string>& messages);

  // Queues one message (the binary zero that ends it is added). When SSR
  // reads nothing for so long that the queue passes its limit, the
  // connection is dropped and made again.
  void send(const std::string& message);
  // Writes what is queued, waiting at most `timeout`; true when all of it went.
  bool flush(std::chrono::milliseconds timeout);

  bool connected() const { return state_ == State::Connected; }
  int fd() const { return fd_; }            // -1 when there is no socket
  short events() const;                      // what to poll fd() for
  int millisecondsUntilAttempt() const;      // -1: no attempt is due (a socket is open)
  std::string address() const { return host_ + ":" + std::to_string(port_); }

 private:
  enum class State { Waiting, Connecting, Connected };
  void startAttempt();
  bool connectNextAddress();  // false when no address is left
  void fail(const std::string& why);
  Event read(std::vector<std::string>& messages);
  bool write();

  std::string host_;
  int port_;
  State state_ = State::Waiting;
  int fd_ = -1;
  Clock::time_point next_attempt_{};
  addrinfo* addresses_ = nullptr;
  addrinfo* next_address_ = nullptr;
  std::string last_error_;
  bool outage_reported_ = false;
  std::string outgoing_;
  MessageSplitter splitter_;
};

}  // namespace beft::ssr_bridge

// Receives LCM's UDP multicast traffic on a socket of the process's own, read
// in the caller's thread.
//
// Why not LCM's own receive path: LCM 1.3.1's udpm provider reads each
// datagram in a thread of its own and wakes the main thread through a pipe,
// so every message a process hears costs two thread wake-ups and five system
// calls. In a lockstep run every process hears a dozen messages a tick, and on
// a virtual machine that fan-out, not the experts' work, was most of the CPU
// time. This receiver reads every datagram already queued with one call
// (recvmmsg), and a socket nobody waits on wakes nobody: an expert's inputs
// are queued by the kernel and read when its FIRE arrives.
//
// It only receives: LCM still does every publish, and the datagrams are
// LCM's own (lcm_wire.hpp), so lcm-spy, lcm-logger and other machines hear
// the same traffic. Each socket carries its own kernel filter (udpm_filter),
// but one that takes every channel (a recorder's).
#pragma once

#include <netinet/in.h>
#include <sys/socket.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "lib/transport/detail/lcm_wire.hpp"
#include "lib/transport/detail/udpm_filter.hpp"

namespace beft::udpm {

// What a udpm:// URL says: "udpm://GROUP:PORT?ttl=N&recv_buf_size=BYTES".
struct Endpoint {
  std::string group = "239.255.76.67";  // LCM's default
  int port = 7667;                      // LCM's default
  int ttl = 0;
  int recv_buf_size = 0;                // [bytes] asked of the kernel, 0: its default
};

// nullopt for another provider (memq://, file://) or a URL that does not parse;
// `why` then says which.
std::optional<Endpoint> parseUrl(const std::string& url, std::string* why = nullptr);

using MessageHandler = transport::Handler;

class Receiver {
 public:
  // Opens, filters, binds and joins the group. Throws std::runtime_error with
  // the reason if any step fails. `batch` datagrams are read per system call.
  Receiver(const Endpoint& endpoint, udpm_filter::Spec spec, std::size_t batch = 16);
  ~Receiver();
  Receiver(const Receiver&) = delete;
  Receiver& operator=(const Receiver&) = delete;

  int fd() const { return fd_; }

  // Reads every datagram queued now, without waiting, and hands each complete
  // message the filter accepts to `handler` in arrival order (the bytes are
  // valid during the call). Returns the number handed on, -1 if the socket
  // failed (errno set).
  int drain(const MessageHandler& handler);

  // Waits up to `timeout_ms` (-1: no limit) for a datagram, then drains.
  // Returns what drain returns, 0 on time-out or a signal.
  int receive(int timeout_ms, const MessageHandler& handler);

  struct Stats {
    uint64_t datagrams = 0;        // read from the socket
    uint64_t messages = 0;         // handed on
    uint64_t invalid = 0;          // not LCM datagrams, or malformed
    uint64_t kernel_dropped = 0;   // lost because the socket's buffer was full (SO_RXQ_OVFL);
                                   // counted only when countsLosses()
    uint64_t incomplete = 0;       // fragmented messages dropped unfinished
  };
  Stats stats() const;
  // True for a socket that takes every channel: it has no kernel filter (the
  // kernel's drop count would include what a filter drops) and counts what
  // the kernel dropped for want of buffer space.
  bool countsLosses() const;
  int receiveBufferBytes() const;  // what the kernel granted

 private:
  void handleDatagram(std::size_t index, std::size_t size, const MessageHandler& handler);

  int fd_ = -1;
  udpm_filter::Spec spec_;
  std::size_t batch_;
  std::vector<uint8_t> buffers_;
  std::vector<uint8_t> controls_;
  std::vector<sockaddr_in> sources_;
  std::vector<mmsghdr> headers_;
  std::vector<iovec> vectors_;
  lcm_wire::FragmentAssembler assembler_;
  Stats stats_;
  uint32_t last_overflow_count_ = 0;
  bool overflow_seen_ = false;
};

// Waits until one of `fds` (at most four; a negative one is left out) is
// readable or `timeout_ms` passes (-1: no limit). Returns true if one is
// readable; false on time-out or a signal. Allocates nothing: it runs on
// every wait of the lockstep loop, and in the arbiter's poll.
bool waitReadable(std::initializer_list<int> fds, int timeout_ms);

}  // namespace beft::udpm

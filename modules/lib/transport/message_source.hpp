// Where a process's incoming messages come from, whatever the LCM provider:
// on a udpm:// URL a socket of its own read in the caller's thread
// (udpm_receiver.hpp); on any other URL (memq:// in tests, file://), or with
// BEFT_UDPM_RECEIVER=0 in the environment, LCM's own receive thread.
// Either way the process waits on fd() (poll) and takes what is there with
// drain(); the spec says which messages it gets.
#pragma once

#include <memory>
#include <string>

#include "udpm_receiver.hpp"

namespace lcm {
class LCM;
}

namespace beft {

class MessageSource {
 public:
  virtual ~MessageSource() = default;
  // Readable while messages wait.
  virtual int fd() const = 0;
  // Hands every message waiting now to `handler`, in arrival order, without
  // waiting for more. Returns how many, -1 if receiving failed.
  virtual int drain(const udpm::MessageHandler& handler) = 0;
  // Waits up to `timeout_ms` for a message, then drains. 0 on time-out or a signal.
  int receive(int timeout_ms, const udpm::MessageHandler& handler);
  // One line for the process's log: how it receives and what.
  virtual std::string description() const = 0;
  // The kernel receive buffer of the direct receiver's socket [bytes]; -1
  // for LCM's own receive path.
  virtual int receiveBufferBytes() const { return -1; }
  // Datagrams the kernel dropped for want of buffer space, where known (a
  // direct receiver of every channel).
  virtual uint64_t kernelDropped() const { return 0; }
};

// True when `url` gets the direct receiver; otherwise `why` says why not.
bool directReceiveFor(const std::string& url, std::string* why = nullptr);

// The direct receiver when directReceiveFor(url), else a subscription of
// `lcm` to what `spec` accepts (with the kernel filter on LCM's socket, which
// a process has only one of: open one such source per LCM instance). Throws
// std::runtime_error if the socket cannot be opened.
std::unique_ptr<MessageSource> openMessageSource(lcm::LCM& lcm, const std::string& url,
                                                 const udpm_filter::Spec& spec, std::size_t batch = 16,
                                                 int lcm_queue_capacity = 10000);

// A process that sleeps on some channels and reads others when it chooses
// (an expert's inputs when its FIRE comes, the blackboard's stored traffic
// every few milliseconds). On the direct receiver: two sockets, `wake` and
// `queued`, which nothing waits on and which takes none of wake's channels.
// Otherwise one LCM subscription takes both, in `wake`, and `queued` is null.
// `queued` is null too when it would take nothing. `wake` must list what it
// takes (AcceptListed). Throws std::runtime_error as openMessageSource does.
struct SplitSources {
  std::unique_ptr<MessageSource> wake, queued;
};
SplitSources openSplitSources(lcm::LCM& lcm, const std::string& url, const udpm_filter::Spec& wake,
                              const udpm_filter::Spec& queued, std::size_t queued_batch = 16,
                              int lcm_queue_capacity = 10000);

// Whether a source with this kernel receive buffer (-1: LCM's own thread,
// which queues in the process) may be read in batches: that needs room for a
// few ticks of camera frames, 2 MiB. When not, says so in the log.
bool roomToGather(int receive_buffer_bytes);

}  // namespace beft

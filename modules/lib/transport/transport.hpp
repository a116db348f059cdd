// How a process receives the run's LCM traffic: the one API the rest of the
// project uses. Say what to take (a Selection: channels, or messages of a
// channel whose encoded bytes match), open a Receiver, wait on its fd() and
// take what came with drain(). LCM still does every publish.
//
// Inside (detail/, private to this library): on a udpm:// URL each receiver
// is a socket of the process's own, read in the caller's thread with one
// recvmmsg for everything queued, with a kernel (BPF) filter built from the
// selection, and LCM's datagrams put back together here (LCM 1.3.1's own
// receive thread costs two wake-ups and five system calls per message). On
// any other URL (memq:// in tests, file://), or with BEFT_UDPM_RECEIVER=0 in
// the environment, LCM's own receive thread, with the same selection.
// Either way every message's envelope comes off, and what was lost on the
// way is asked for again and handed on in order (publisher.hpp,
// detail/stream_tracker.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lcm {
class LCM;
}

namespace beft::transport {

// One received message; its bytes are valid during the handler call only.
struct Message {
  std::string_view channel;
  const uint8_t* data = nullptr;
  std::size_t size = 0;
  int64_t recv_utime = 0;  // receive time of its last datagram [us since the epoch]
};
using Handler = std::function<void(const Message&)>;

// A message matches when its channel is `channel` and, when `field` is not
// empty, the encoded message (after its 8-byte fingerprint) holds exactly the
// bytes `field` at `field_offset` (control_messages.hpp builds such rules).
struct Rule {
  std::string channel;
  std::size_t field_offset = 0;  // [bytes] from the first byte after the fingerprint
  std::string field;             // encoded bytes that must be there
  std::string what;              // what the field selects, for the log ("own firings")
};

// Every message on one channel.
Rule channelRule(const std::string& channel);

// Which messages a receiver takes: those its rules match (AcceptListed), or
// all but those (RejectListed: a recorder's "everything").
// Channels are named as in channels.hpp; the receiver takes them on this
// process's run (run_identity.hpp: "VISION@<run>") and hands them on under
// their plain names, dropping (and counting) any other run's, unless
// every_run (the recorder: every run's channels, names as heard).
struct Selection {
  enum class Mode { AcceptListed, RejectListed };
  Mode mode = Mode::AcceptListed;
  std::vector<Rule> rules;
  bool every_run = false;
};

// True when an LCM subscription pattern is a plain channel name (no regex).
bool isPlainChannel(const std::string& pattern);

// What loss repair did on a receiver (detail/stream_tracker.hpp).
struct RepairStats {
  uint64_t gaps = 0;             // messages found missing
  uint64_t repaired = 0;         // of those, got by repair
  uint64_t lost = 0;             // of those, given up (the sender no longer had them, or died)
  uint64_t duplicates = 0;       // copies dropped
  uint64_t joined_late = 0;      // streams first heard after their early messages
  uint64_t requests = 0;         // repair requests sent
  uint64_t unauthenticated = 0;  // refused in a run with a key: no valid tag
  uint64_t waiting = 0;          // messages held now behind a gap
  uint64_t outstanding = 0;      // messages missing now, still asked for
  std::vector<std::string> lost_named;  // the first few given up: "CHANNEL #N of PROCESS (why)"
};

class Receiver {
 public:
  virtual ~Receiver() = default;
  // Readable while messages wait.
  virtual int fd() const = 0;
  // Hands every message waiting now to `handler`, in arrival order, without
  // waiting for more. Returns how many, -1 if receiving failed.
  virtual int drain(const Handler& handler) = 0;
  // Waits up to `timeout_ms` for a message, then drains. 0 on time-out or a signal.
  int receive(int timeout_ms, const Handler& handler);
  // One line for the process's log: how it receives and what.
  virtual std::string description() const = 0;
  // The kernel receive buffer of the direct receiver's socket [bytes]; -1
  // for LCM's own receive path.
  virtual int receiveBufferBytes() const { return -1; }
  // Datagrams the kernel dropped for want of buffer space, where known (a
  // direct receiver of every channel).
  virtual uint64_t kernelDropped() const { return 0; }
  virtual RepairStats repairStats() const { return {}; }
  // Whether message `sequence` of `sender` on `channel` (plain name) has been
  // handed on, or never will be (not a channel taken whole here, or its
  // sender is gone). When not, it is asked for shortly (it may still be on
  // its way): drain on as usual and ask again. A FIRE lists what it comes
  // after (lib/expert/frontier.hpp).
  // A process restarted mid-run (its state rebuilt from the run's log) is
  // owed nothing of a stream it has not heard: `owed_unheard` false.
  virtual bool holds(uint64_t sender, const std::string& channel, uint64_t sequence, bool owed_unheard = true) {
    (void)sender, (void)channel, (void)sequence, (void)owed_unheard;
    return true;
  }
};

// True when `url` gets the direct receiver; otherwise `why` says why not.
bool directReceiveFor(const std::string& url, std::string* why = nullptr);

// The direct receiver when directReceiveFor(url), else a subscription of
// `lcm` to what `selection` accepts (with the kernel filter on LCM's socket,
// which a process has only one of: open one such receiver per LCM instance).
// `batch` datagrams are read per system call. Throws std::runtime_error if
// the socket cannot be opened.
std::unique_ptr<Receiver> openReceiver(lcm::LCM& lcm, const std::string& url, const Selection& selection,
                                       std::size_t batch = 16, int lcm_queue_capacity = 10000);

// A process that sleeps on some channels and reads others when it chooses
// (an expert's inputs when its FIRE comes, the blackboard's stored traffic
// every few milliseconds). On the direct receiver: two sockets, `wake` and
// `queued`, which nothing waits on and which takes none of wake's channels.
// Otherwise one LCM subscription takes both, in `wake`, and `queued` is null.
// `queued` is null too when it would take nothing. `wake` must list what it
// takes (AcceptListed). Throws std::runtime_error as openReceiver does.
struct SplitReceivers {
  std::unique_ptr<Receiver> wake, queued;
};
SplitReceivers openSplitReceivers(lcm::LCM& lcm, const std::string& url, const Selection& wake,
                                  const Selection& queued, std::size_t queued_batch = 16,
                                  int lcm_queue_capacity = 10000);

// One pass over a split pair before serving what `wake` brought (a FIRE, a
// plan request, a query) with what `queued` holds (the inputs it needs):
// queued, wake, then queued again. What was published before a wake message
// is then handed over before the pass ends, even if it arrived while `wake`
// was drained (draining `queued` only first would leave it for the next
// pass, and the wake message would be served without it). `queued` may be
// null. Returns how many messages were handed over, -1 if receiving failed.
int drainSplit(Receiver& wake, Receiver* queued, const Handler& handler);

// Whether a receiver with this kernel receive buffer (-1: LCM's own thread,
// which queues in the process) may be read in batches: that needs room for a
// few ticks of camera frames, 2 MiB. When not, says so in the log.
bool roomToGather(int receive_buffer_bytes);

// Waits until one of `fds` is readable (a negative fd is skipped) or
// `timeout_ms` passes (0: just looks). True if one is readable.
bool waitReadable(std::initializer_list<int> fds, int timeout_ms);

// The port of a udpm:// URL, or -1 for any other provider.
int udpmPort(const std::string& url);

}  // namespace beft::transport

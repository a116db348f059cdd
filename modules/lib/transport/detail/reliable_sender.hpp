// The sender's side of loss repair on a udpm:// URL, in a thread of the
// process's own beside its publishing:
//  - serves repair requests (BEFT_REPAIR, a negative acknowledgement as in
//    PGM and NORM) addressed to this sender: the kernel filter passes only
//    those; every message asked for is published again from the copies kept;
//  - says what it has sent (BEFT_SENDERS): once it has been quiet for a
//    moment after publishing (a receiver that missed the last message of a
//    burst learns of it within milliseconds), then at a slowing pace, every
//    half second at most, as a heartbeat (receivers keep asking a sender
//    they hear, and give up on one they no longer hear).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "lib/transport/detail/repair_buffer.hpp"

namespace beft::transport::detail {

class ReliableSender {
 public:
  struct Hooks {
    uint64_t sender = 0;
    std::string process;
    // Publishes a kept message again; false when it is no longer kept.
    std::function<bool(const std::string& channel, uint64_t sequence)> resend;
    std::function<std::vector<RepairBuffer::ChannelState>()> state;
    // Publishes an encoded control message (with its envelope) on a channel as sent.
    std::function<void(const std::string& channel, const std::vector<uint8_t>& encoded)> publish;
  };

  // Quiet time after a publish before the state goes out [ms].
  static constexpr int kQuietMs = 1;
  // Heartbeat states: from kQuietMs doubling up to this [ms].
  static constexpr int kSlowestStateMs = 500;
  // While leaving, the state goes out this often [ms]: a receiver that lost
  // the leaving state (and with it news of a last message it missed) hears
  // the next one while the sender still answers.
  static constexpr int kLeavingStateMs = 20;

  // Null for a URL that is not udpm:// (nothing there is lost). Throws
  // std::runtime_error when the repair socket cannot be opened.
  static std::unique_ptr<ReliableSender> startFor(const std::string& url, Hooks hooks);
  ~ReliableSender();
  ReliableSender(const ReliableSender&) = delete;
  ReliableSender& operator=(const ReliableSender&) = delete;

  // Called after every publish: cheap (a write to an eventfd at the start of a burst only).
  void published();
  // Before the process ends: says so (a state with `leaving`), then serves
  // repair requests until none came for `quiet_ms`, `longest_ms` at most, so
  // that a receiver that missed the last messages still gets them.
  void leave(int quiet_ms, int longest_ms);

  struct Stats {
    uint64_t requests = 0;      // repair requests heard
    uint64_t resent = 0;        // messages published again
    uint64_t not_kept = 0;      // asked for but no longer kept
    uint64_t states = 0;        // states sent
  };
  Stats stats() const;

 private:
  ReliableSender(std::string url, Hooks hooks);
  void run();

  struct Loop;
  const std::string url_;
  Hooks hooks_;
  int wake_fd_ = -1;
  std::atomic<bool> stop_{false};
  std::atomic<bool> dirty_{false};
  std::atomic<bool> leaving_{false};
  std::atomic<bool> ever_published_{false};
  std::atomic<int64_t> last_request_us_{0};
  std::atomic<int64_t> last_publish_us_{0};
  std::atomic<uint64_t> requests_{0}, resent_{0}, not_kept_{0}, states_{0};
  std::thread thread_;
};

}  // namespace beft::transport::detail

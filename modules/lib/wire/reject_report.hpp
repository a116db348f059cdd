// What a process refused, told to the run: the totals of its reject counter
// (reject_counter.hpp) in a PROCESS_REJECTS message whenever they changed,
// looked at once a period from a thread of its own, and a last time when it
// stops. A process that refuses nothing sends nothing. The report adds up
// the last message of each process: a run's log keeps no envelopes, so what
// a keyed run refused for want of a valid tag is known only to the
// processes that refused it.
//
//   wire::RejectReporter rejects(process_name, [&lcm](const beft::process_rejects_t& account) {
//     transport::publish(lcm, wire::runChannel(channels::kProcessRejects), account);
//   });
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <beft/process_rejects_t.hpp>

#include "lib/wire/reject_counter.hpp"

namespace beft::wire {

// The account of `counter` for a process; utime, final and the counts filled.
beft::process_rejects_t rejectAccount(const RejectCounter& counter, const std::string& process, bool final);

// True when two accounts hold the same counts.
bool sameCounts(const beft::process_rejects_t& a, const beft::process_rejects_t& b);

class RejectReporter {
 public:
  using Publish = std::function<void(const beft::process_rejects_t&)>;
  RejectReporter(std::string process, Publish publish, const RejectCounter& counter = processRejects(),
                 std::chrono::milliseconds period = std::chrono::seconds(1));
  // Stops the thread, then sends the last account (final) when anything was refused.
  ~RejectReporter();
  RejectReporter(const RejectReporter&) = delete;
  RejectReporter& operator=(const RejectReporter&) = delete;

  int sent() const;

 private:
  void loop();
  void sendIfChanged(bool final);

  const std::string process_;
  const Publish publish_;
  const RejectCounter& counter_;
  const std::chrono::milliseconds period_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::optional<beft::process_rejects_t> last_sent_;
  int sent_ = 0;
  std::thread thread_;
};

}  // namespace beft::wire

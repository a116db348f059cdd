#include "lib/wire/reject_report.hpp"

#include <unistd.h>

#include "lib/common/clocks.hpp"

namespace beft::wire {

namespace {

std::string hostName() {
  char name[256] = {0};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

}  // namespace

beft::process_rejects_t rejectAccount(const RejectCounter& counter, const std::string& process, bool final) {
  beft::process_rejects_t account{};
  account.utime = wallMicros();
  account.process = process;
  account.pid = static_cast<int32_t>(getpid());
  account.host = hostName();
  for (const auto& [fault, count] : counter.faultTotals()) {
    const auto messages = static_cast<int64_t>(count);
    if (fault == Fault::kUnauthenticated) account.unauthenticated += messages;
    else if (fault == Fault::kOtherRun) account.other_run += messages;
    else account.malformed += messages;  // refused by the guard or a payload's reader
  }
  account.final = final;
  return account;
}

bool sameCounts(const beft::process_rejects_t& a, const beft::process_rejects_t& b) {
  return a.unauthenticated == b.unauthenticated && a.other_run == b.other_run && a.malformed == b.malformed;
}

RejectReporter::RejectReporter(std::string process, Publish publish, const RejectCounter& counter,
                               std::chrono::milliseconds period)
    : process_(std::move(process)), publish_(std::move(publish)), counter_(counter), period_(period) {
  thread_ = std::thread([this] { loop(); });
}

RejectReporter::~RejectReporter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
  sendIfChanged(true);
}

int RejectReporter::sent() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return sent_;
}

void RejectReporter::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, period_, [this] { return stop_; })) {
    lock.unlock();
    sendIfChanged(false);
    lock.lock();
  }
}

// Only the reporter's thread, then its destructor, get here: one at a time.
// The last account goes out even when unchanged: it says the process stopped.
void RejectReporter::sendIfChanged(bool final) {
  const beft::process_rejects_t account = rejectAccount(counter_, process_, final);
  if (account.unauthenticated + account.other_run + account.malformed == 0) return;
  if (!final && last_sent_ && sameCounts(*last_sent_, account)) return;
  publish_(account);  // not under the lock: a publish may take its time
  std::lock_guard<std::mutex> lock(mutex_);
  last_sent_ = account;
  ++sent_;
}

}  // namespace beft::wire

// A process's account of what it refused (PROCESS_REJECTS): the counter's
// totals by reason, sent when they change and a last time at the end.
#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include "lib/wire/reject_report.hpp"

using beft::wire::Fault;
using beft::wire::RejectCounter;
using beft::wire::RejectReporter;

namespace {

struct Sent {
  std::mutex mutex;
  std::vector<beft::process_rejects_t> accounts;
  RejectReporter::Publish publish() {
    return [this](const beft::process_rejects_t& account) {
      std::lock_guard<std::mutex> lock(mutex);
      accounts.push_back(account);
    };
  }
  std::size_t size() {
    std::lock_guard<std::mutex> lock(mutex);
    return accounts.size();
  }
};

// Waits (at most 10 s: not a timing assertion) until `sent` holds `count` accounts.
bool waitFor(Sent& sent, std::size_t count) {
  for (int i = 0; i < 1000 && sent.size() < count; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  return sent.size() >= count;
}

}  // namespace

TEST(RejectAccount, SortsTheCountsByReason) {
  RejectCounter counter;
  counter.count("FIRE", {Fault::kUnauthenticated, ""});
  counter.count("DONE", {Fault::kUnauthenticated, ""});
  counter.count("FIRE", {Fault::kOtherRun, "", 7});
  counter.count("VISION", {Fault::kTrailingBytes, ""});
  counter.count("VISION", {Fault::kBadPayload, ""});
  counter.count("VISION", {Fault::kTooShort, ""});
  const auto account = beft::wire::rejectAccount(counter, "vision", false);
  EXPECT_EQ(account.process, "vision");
  EXPECT_EQ(account.unauthenticated, 2);
  EXPECT_EQ(account.other_run, 1);
  EXPECT_EQ(account.malformed, 3);
  EXPECT_FALSE(account.final);
  EXPECT_GT(account.pid, 0);
  EXPECT_EQ(counter.totalOf(Fault::kUnauthenticated), 2u);
  EXPECT_EQ(counter.totalOf(Fault::kUndecodable), 0u);
}

TEST(RejectReporter, AProcessThatRefusedNothingSendsNothing) {
  RejectCounter counter;
  Sent sent;
  {
    RejectReporter reporter("world", sent.publish(), counter, std::chrono::milliseconds(5));
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
  }
  EXPECT_EQ(sent.size(), 0u);
}

TEST(RejectReporter, SendsWhatChangedOnceAndALastAccountWhenItStops) {
  RejectCounter counter;
  Sent sent;
  {
    RejectReporter reporter("tasks", sent.publish(), counter, std::chrono::milliseconds(5));
    counter.count("TASK_COMMAND", {Fault::kUnauthenticated, ""});
    ASSERT_TRUE(waitFor(sent, 1));
    // Unchanged counts: nothing more while it runs.
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    EXPECT_EQ(sent.size(), 1u);
    counter.count("TASK_COMMAND", {Fault::kUnauthenticated, ""});
    ASSERT_TRUE(waitFor(sent, 2));
    counter.count("FIRE", {Fault::kUnauthenticated, ""});
  }
  ASSERT_GE(sent.accounts.size(), 3u);
  EXPECT_EQ(sent.accounts[0].unauthenticated, 1);
  EXPECT_FALSE(sent.accounts[0].final);
  EXPECT_EQ(sent.accounts[1].unauthenticated, 2);
  const auto& last = sent.accounts.back();
  EXPECT_TRUE(last.final);
  EXPECT_EQ(last.unauthenticated, 3);
  EXPECT_EQ(last.process, "tasks");
}

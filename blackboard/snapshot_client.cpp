#include "blackboard/snapshot_client.hpp"

#include <algorithm>
#include <chrono>
#include <random>

#include <beft/bb_query_t.hpp>

#include "blackboard/snapshot.hpp"
#include "lib/common/channels.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::blackboard {
namespace {

int64_t wallUtime() {
  using namespace std::chrono;
  return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

// Unique enough that two clients sharing a requester name never take each
// other's answers.
int64_t newQueryId() {
  std::random_device device;
  std::mt19937_64 generator((static_cast<uint64_t>(device()) << 32) ^ device() ^
                            static_cast<uint64_t>(wallUtime()));
  return static_cast<int64_t>(generator() >> 1);
}

class SnapshotWaiter {
 public:
  explicit SnapshotWaiter(int64_t query_id) : query_id_(query_id) {}
  // A plain function for LCM's subscribeFunction: the member-pointer
  // subscribe crashes under GCC's -fsanitize=vptr (see the top-level CMakeLists).
  static void onSnapshot(const lcm::ReceiveBuffer*, const std::string&, const beft::bb_snapshot_t* snapshot,
                         SnapshotWaiter* self) {
    if (!self->answer_ && snapshot->query_id == self->query_id_) self->answer_ = *snapshot;
  }
  std::optional<beft::bb_snapshot_t>& answer() { return answer_; }

 private:
  int64_t query_id_;
  std::optional<beft::bb_snapshot_t> answer_;
};

}  // namespace

std::optional<beft::bb_snapshot_t> requestSnapshot(lcm::LCM& lcm, const std::string& requester,
                                                   const std::vector<std::string>& channels, double timeout_s) {
  using Clock = std::chrono::steady_clock;
  if (!lcm.good()) return std::nullopt;

  beft::bb_query_t query{};
  query.requester = requester;
  query.query_id = newQueryId();
  query.channels = channels;
  query.num_channels = static_cast<int32_t>(channels.size());

  SnapshotWaiter waiter(query.query_id);
  lcm::Subscription* subscription =
      lcm.subscribeFunction(wire::runChannel(snapshotChannel(requester)), &SnapshotWaiter::onSnapshot, &waiter);
  // One answer is expected; a few more only if re-sent queries cross it.
  subscription->setQueueCapacity(4);

  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(std::max(0.0, timeout_s)));
  const auto resend_period = std::chrono::milliseconds(500);
  auto next_send = Clock::now();
  while (!waiter.answer()) {
    const auto now = Clock::now();
    if (now >= deadline) break;
    if (now >= next_send) {
      query.utime = wallUtime();
      transport::publish(lcm, wire::runChannel(channels::kBlackboardQuery), query);
      next_send = now + resend_period;
    }
    const auto wait = std::min(deadline, next_send) - now;
    const int wait_ms =
        std::max(1, static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(wait).count()));
    if (lcm.handleTimeout(wait_ms) < 0) break;
  }
  lcm.unsubscribe(subscription);
  return std::move(waiter.answer());
}

std::vector<beft::bb_entry_t> fetchSnapshot(lcm::LCM& lcm, const std::string& requester,
                                            const std::vector<std::string>& channels, double timeout_s,
                                            bool* answered) {
  auto snapshot = requestSnapshot(lcm, requester, channels, timeout_s);
  if (answered) *answered = snapshot.has_value();
  if (!snapshot) return {};
  return std::move(snapshot->entries);
}

}  // namespace beft::blackboard

// The expert framework: FIRE/DONE protocol on a real LCM bus, parameters,
// and replay against a recorded log.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <mutex>
#include <thread>

#include <beft/bb_query_t.hpp>
#include <beft/bb_snapshot_t.hpp>
#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/heartbeat_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/run_status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/wire/channel_history.hpp"
#include "lib/common/channels.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/expert/hypotheses_input.hpp"
#include "lib/expert/live_runner.hpp"
#include "lib/expert/log_replay.hpp"

using namespace beft;
using namespace std::chrono_literals;

namespace {

constexpr channels::Channel<beft::robot_state_t> kScaled{"SCALED"};

// Doubles the robot's x: reads ROBOT_STATE, writes it scaled on "SCALED".
class ScalingExpert : public expert::Expert {
 public:
  std::string name() const override { return "scaler"; }
  std::string description() const override { return "test expert"; }
  bool inputsReady(const expert::Firing& f) const override { return states_.at(f.utime) != nullptr; }
  expert::Outcome fire(const expert::Firing& f, expert::Output& out) override {
    fires.fetch_add(1);
    const auto* entry = states_.at(f.utime);
    if (!entry) return expert::Outcome::failure("no robot state for tick");
    beft::robot_state_t scaled = entry->message;
    scaled.x *= factor_;
    scaled_out_.publish(out, scaled);
    return expert::Outcome::success();
  }
  std::atomic<int> fires{0};

 protected:
  void declareParameters(DeclaredParameters& parameters) override {
    parameters.declare("factor", factor_, 0, 100, "scale of x");
  }

 private:
  double factor_ = 2.0;
  blackboard::ChannelHistory<beft::robot_state_t> states_;
  expert::HandledInput<beft::robot_state_t> robot_{
      *this, channels::kRobotState, [this](beft::robot_state_t&& s) { states_.store(s, s.utime); }};
  expert::OutputPort<beft::robot_state_t> scaled_out_{*this, kScaled};
};

// Reads nothing and works on its firing until the test lets it finish (at
// most a minute), like the task executor waiting for a plan.
class SlowExpert : public expert::Expert {
 public:
  std::string name() const override { return "slow"; }
  std::string description() const override { return "test expert"; }
  expert::Outcome fire(const expert::Firing&, expert::Output&) override {
    std::unique_lock<std::mutex> lock(mutex_);
    working_ = true;
    changed_.notify_all();
    changed_.wait_for(lock, 60s, [this] { return released_; });
    return expert::Outcome::success();
  }
  bool working() {
    std::lock_guard<std::mutex> lock(mutex_);
    return working_;
  }
  void release() {
    std::lock_guard<std::mutex> lock(mutex_);
    released_ = true;
    changed_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  bool working_ = false, released_ = false;
};

int uniquePort(int offset) { return 21000 + (getpid() * 7 + offset) % 9000; }

beft::robot_state_t stateAt(int64_t tick, double x) {
  beft::robot_state_t s{};
  s.utime = tick * 100000;
  s.tick = tick;
  s.x = x;
  return s;
}

beft::fire_t fireToken(const std::string& expert_name, int64_t tick, int64_t id) {
  beft::fire_t f{};
  f.utime = tick * 100000;
  f.expert = expert_name;
  f.transition = "t_" + expert_name;
  f.tick = tick;
  f.firing_id = id;
  return f;
}

struct DoneCollector {
  std::mutex mutex;
  std::vector<beft::done_t> done;
  std::vector<beft::robot_state_t> scaled;
  int heartbeats = 0;
  void onDone(const lcm::ReceiveBuffer*, const std::string&, const beft::done_t* d) {
    std::lock_guard<std::mutex> lock(mutex);
    done.push_back(*d);
  }
  void onScaled(const lcm::ReceiveBuffer*, const std::string&, const beft::robot_state_t* s) {
    std::lock_guard<std::mutex> lock(mutex);
    scaled.push_back(*s);
  }
  void onHeartbeat(const lcm::ReceiveBuffer*, const std::string&, const beft::heartbeat_t* h) {
    std::lock_guard<std::mutex> lock(mutex);
    ++heartbeats;
    beats.push_back(*h);
  }
  std::vector<beft::heartbeat_t> beats;

  size_t doneCount() {
    std::lock_guard<std::mutex> lock(mutex);
    return done.size();
  }
  int heartbeatCount() {
    std::lock_guard<std::mutex> lock(mutex);
    return heartbeats;
  }
  int beatsIn(const std::string& state) {
    std::lock_guard<std::mutex> lock(mutex);
    return static_cast<int>(std::count_if(beats.begin(), beats.end(), [&](const auto& b) { return b.state == state; }));
  }
  bool lastBeatIs(const std::string& state, int64_t last_firing_id) {
    std::lock_guard<std::mutex> lock(mutex);
    return !beats.empty() && beats.back().state == state && beats.back().last_firing_id == last_firing_id;
  }
};

// The options of a live "scaler" on its own port, without blackboard catch-up.
expert::LiveOptions scalerOptions(int port_offset) {
  expert::LiveOptions options;
  options.lcm_url = lcmUrlForPort(uniquePort(port_offset));
  options.process_name = "scaler";
  options.catch_up = false;
  return options;
}

// Handles the bus until `condition` holds; false if it still does not after
// a generous deadline (the machine is shared: never a short window).
bool pumpUntil(lcm::LCM& lcm, const std::function<bool()>& condition, std::chrono::seconds deadline = 30s) {
  const auto end = std::chrono::steady_clock::now() + deadline;
  while (!condition()) {
    if (std::chrono::steady_clock::now() >= end) return false;
    lcm.handleTimeout(10);
  }
  return true;
}

// The runner sends its first heartbeat once it listens: from then on
// nothing published to it is lost.
bool waitUntilListening(lcm::LCM& lcm, DoneCollector& collector) {
  return pumpUntil(lcm, [&] { return collector.heartbeatCount() >= 1; });
}

}  // namespace

TEST(LiveRunner, FiresOncePerFiringAndRepeatsDoneForDuplicates) {
  ScalingExpert scaler;
  scaler.startUp();
  expert::LiveOptions options = scalerOptions(1);
  options.heartbeat_period_s = 0.05;
  const std::string url = options.lcm_url;
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good());
  DoneCollector collector;
  lcm.subscribe(channels::kDone, &DoneCollector::onDone, &collector);
  lcm.subscribe("SCALED", &DoneCollector::onScaled, &collector);
  lcm.subscribe(channels::kHeartbeat, &DoneCollector::onHeartbeat, &collector);
  std::atomic<int> exit_code{-1};
  std::thread runner([&] { exit_code = expert::runLive(scaler, options); });
  EXPECT_TRUE(waitUntilListening(lcm, collector));

  const auto state = stateAt(3, 1.5);
  lcm.publish(channels::kRobotState, &state);
  const auto fire = fireToken("scaler", 3, 10);
  lcm.publish(channels::kFire, &fire);
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 1; }));
  lcm.publish(channels::kFire, &fire);  // a re-send: DONE again, no second run
  const auto other = fireToken("someone_else", 3, 11);
  lcm.publish(channels::kFire, &other);
  const auto stale = fireToken("scaler", 2, 9);
  lcm.publish(channels::kFire, &stale);
  // The next firing's DONE comes after whatever the three above caused.
  const auto next_state = stateAt(4, 0.25);
  lcm.publish(channels::kRobotState, &next_state);
  const auto next = fireToken("scaler", 4, 12);
  lcm.publish(channels::kFire, &next);
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 3; }));
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.heartbeatCount() >= 2; }));

  beft::run_status_t end{};
  end.state = beft::run_status_t::STATE_FINISHED;
  end.message = "test over";
  lcm.publish(channels::kRunStatus, &end);
  runner.join();

  EXPECT_EQ(exit_code.load(), 0);
  EXPECT_EQ(scaler.fires.load(), 2);
  std::lock_guard<std::mutex> lock(collector.mutex);
  ASSERT_EQ(collector.done.size(), 3u);
  const int64_t expected_ids[] = {10, 10, 12};
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(collector.done[i].firing_id, expected_ids[i]);
    EXPECT_EQ(collector.done[i].expert, "scaler");
    EXPECT_EQ(collector.done[i].outcome, beft::done_t::OUTCOME_OK);
  }
  ASSERT_EQ(collector.scaled.size(), 2u);
  EXPECT_DOUBLE_EQ(collector.scaled[0].x, 3.0);
  EXPECT_DOUBLE_EQ(collector.scaled[1].x, 0.5);
  EXPECT_GE(collector.heartbeats, 2);
}

// A restarted arbiter whose log lacked a FIRE sends it again under a new
// id: the expert answers with its DONE under that id and sends nothing twice;
// after a failed firing, or for another tick, it runs again.
TEST(LiveRunner, AFiringDoneAndFiredAgainUnderANewIdIsNotRunTwice) {
  ScalingExpert scaler;
  scaler.startUp();
  expert::LiveOptions options = scalerOptions(6);
  options.ready_timeout_s = 0.2;  // tick 5 fails for want of its input, at once
  const std::string url = options.lcm_url;
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good());
  DoneCollector collector;
  lcm.subscribe(channels::kDone, &DoneCollector::onDone, &collector);
  lcm.subscribe("SCALED", &DoneCollector::onScaled, &collector);
  lcm.subscribe(channels::kHeartbeat, &DoneCollector::onHeartbeat, &collector);
  std::thread runner([&] { expert::runLive(scaler, options); });
  EXPECT_TRUE(waitUntilListening(lcm, collector));

  const auto state = stateAt(3, 1.5);
  lcm.publish(channels::kRobotState, &state);
  const auto first = fireToken("scaler", 3, 10);
  lcm.publish(channels::kFire, &first);
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 1; }));
  const auto again = fireToken("scaler", 3, 13);  // the same transition and tick, a new id
  lcm.publish(channels::kFire, &again);
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 2; }));
  const auto failing = fireToken("scaler", 5, 14);  // no ROBOT_STATE of tick 5: fails after the timeout
  lcm.publish(channels::kFire, &failing);
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 3; }));
  const auto state5 = stateAt(5, 4.0);
  lcm.publish(channels::kRobotState, &state5);
  const auto retried = fireToken("scaler", 5, 15);  // after a failure the firing runs again
  lcm.publish(channels::kFire, &retried);
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 4; }));
  beft::run_status_t end{};
  end.state = beft::run_status_t::STATE_FINISHED;
  lcm.publish(channels::kRunStatus, &end);
  runner.join();

  std::lock_guard<std::mutex> lock(collector.mutex);
  ASSERT_EQ(collector.done.size(), 4u);
  const int64_t expected_ids[] = {10, 13, 14, 15};
  const int8_t expected_outcomes[] = {beft::done_t::OUTCOME_OK, beft::done_t::OUTCOME_OK,
                                      beft::done_t::OUTCOME_FAILED, beft::done_t::OUTCOME_OK};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(collector.done[i].firing_id, expected_ids[i]);
    EXPECT_EQ(collector.done[i].outcome, expected_outcomes[i]) << collector.done[i].message;
  }
  EXPECT_EQ(collector.done[1].tick, 3);
  ASSERT_EQ(collector.scaled.size(), 2u) << "tick 3's output sent twice";
  EXPECT_DOUBLE_EQ(collector.scaled[0].x, 3.0);
  EXPECT_DOUBLE_EQ(collector.scaled[1].x, 8.0);
  EXPECT_EQ(scaler.fires.load(), 3);
}

TEST(LiveRunner, AnswersAWaitingArbiterWithAHeartbeatAtOnce) {
  ScalingExpert scaler;
  scaler.startUp();
  expert::LiveOptions options = scalerOptions(3);
  options.heartbeat_period_s = 3600;  // only the first one comes by itself
  const std::string url = options.lcm_url;
  lcm::LCM lcm(url);
  DoneCollector collector;
  lcm.subscribe(channels::kHeartbeat, &DoneCollector::onHeartbeat, &collector);
  std::thread runner([&] { expert::runLive(scaler, options); });
  EXPECT_TRUE(waitUntilListening(lcm, collector));
  EXPECT_EQ(collector.heartbeatCount(), 1);
  beft::run_status_t waiting{};
  waiting.state = beft::run_status_t::STATE_WAITING;
  waiting.message = "waiting for heartbeats from: scaler";
  lcm.publish(channels::kRunStatus, &waiting);
  // The next periodic one is an hour away: a second one is the answer.
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.heartbeatCount() >= 2; })) << "no heartbeat in answer to WAITING";
  EXPECT_EQ(collector.heartbeatCount(), 2);
  beft::run_status_t end{};
  end.state = beft::run_status_t::STATE_FINISHED;
  lcm.publish(channels::kRunStatus, &end);
  runner.join();
}

TEST(LiveRunner, KeepsItsHeartbeatDuringALongFiring) {
  SlowExpert slow;
  expert::LiveOptions options = scalerOptions(4);
  options.process_name = "slow";
  options.heartbeat_period_s = 0.1;
  lcm::LCM lcm(options.lcm_url);
  DoneCollector collector;
  lcm.subscribe(channels::kHeartbeat, &DoneCollector::onHeartbeat, &collector);
  lcm.subscribe(channels::kDone, &DoneCollector::onDone, &collector);
  std::thread runner([&] { expert::runLive(slow, options); });
  EXPECT_TRUE(waitUntilListening(lcm, collector));
  const auto fire = fireToken("slow", 1, 7);
  lcm.publish(channels::kFire, &fire);
  EXPECT_TRUE(pumpUntil(lcm, [&] { return slow.working(); }));
  // While the firing lasts (until released), five more beats say so.
  const int firing_before = collector.beatsIn("firing");
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.beatsIn("firing") >= firing_before + 5; }))
      << "heartbeats stopped while the expert worked on its firing";
  EXPECT_EQ(collector.doneCount(), 0u);
  slow.release();
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 1 && collector.lastBeatIs("idle", 7); }))
      << "no DONE, or no idle heartbeat after it";
  beft::run_status_t end{};
  end.state = beft::run_status_t::STATE_FINISHED;
  lcm.publish(channels::kRunStatus, &end);
  runner.join();

  std::lock_guard<std::mutex> lock(collector.mutex);
  ASSERT_EQ(collector.done.size(), 1u);
  ASSERT_FALSE(collector.beats.empty());
  EXPECT_EQ(collector.beats.front().last_firing_id, -1);
}

TEST(LiveRunner, WaitsForInputsThenFiresAnyway) {
  ScalingExpert scaler;
  scaler.startUp();
  expert::LiveOptions options = scalerOptions(2);
  options.ready_timeout_s = 0.2;
  const std::string url = options.lcm_url;
  lcm::LCM lcm(url);
  DoneCollector collector;
  lcm.subscribe(channels::kDone, &DoneCollector::onDone, &collector);
  lcm.subscribe(channels::kHeartbeat, &DoneCollector::onHeartbeat, &collector);
  std::thread runner([&] { expert::runLive(scaler, options); });
  EXPECT_TRUE(waitUntilListening(lcm, collector));
  const auto fire = fireToken("scaler", 5, 1);
  lcm.publish(channels::kFire, &fire);  // no ROBOT_STATE for tick 5 ever comes
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 1; }));
  beft::run_status_t end{};
  end.state = beft::run_status_t::STATE_FAILED;
  lcm.publish(channels::kRunStatus, &end);
  runner.join();

  std::lock_guard<std::mutex> lock(collector.mutex);
  ASSERT_EQ(collector.done.size(), 1u);
  EXPECT_EQ(collector.done[0].outcome, beft::done_t::OUTCOME_FAILED);
  EXPECT_NE(collector.done[0].message.find("no robot state"), std::string::npos);
}

// Keeps ROBOT_STATE by tick, as the mission's experts do.
class TickReader : public expert::Expert {
 public:
  std::string name() const override { return "reader"; }
  std::string description() const override { return "test expert"; }
  bool inputsReady(const expert::Firing& f) const override { return robot_.has(f.tick); }
  expert::Outcome fire(const expert::Firing& f, expert::Output&) override {
    return robot_.has(f.tick) ? expert::Outcome::success() : expert::Outcome::failure("no robot state for tick");
  }

 private:
  expert::TickInput<beft::robot_state_t> robot_{*this, channels::kRobotState};
};

// The blackboard's side of a refill: answers each query after the first
// with the robot state of tick 5 (the datagram the expert lost).
struct FakeBlackboard {
  lcm::LCM* lcm = nullptr;
  std::atomic<int> queries{0};
  void onQuery(const lcm::ReceiveBuffer*, const std::string&, const beft::bb_query_t* query) {
    ++queries;
    if (query->query_id < 2) return;  // the catch-up at start: nothing stored yet
    beft::robot_state_t state{};
    state.utime = 500000;
    state.tick = 5;
    state.x = 1.5;
    state.last_command = "stop";
    beft::bb_entry_t entry{};
    entry.channel = channels::kRobotState.name;
    entry.sequence = 1;
    entry.utime = state.utime;
    entry.data.resize(state.getEncodedSize());
    state.encode(entry.data.data(), 0, static_cast<int>(entry.data.size()));
    entry.data_size = static_cast<int32_t>(entry.data.size());
    beft::bb_snapshot_t snapshot{};
    snapshot.query_id = query->query_id;
    snapshot.entries.push_back(entry);
    snapshot.num_entries = 1;
    lcm->publish(std::string(channels::kBlackboardSnapshotPrefix) + query->requester, &snapshot);
  }
};

// The input of a FIRE never arrives live (a lost datagram): after
// refill_after_s the expert asks the blackboard again and fires with what it
// holds, instead of firing without it (lockstep stays deterministic).
TEST(LiveRunner, ALostInputIsAskedOfTheBlackboardAgain) {
  TickReader reader;
  reader.startUp();
  expert::LiveOptions options;
  options.lcm_url = lcmUrlForPort(uniquePort(9));
  options.process_name = "reader";
  options.catch_up = true;
  options.refill_after_s = 0.2;
  lcm::LCM lcm(options.lcm_url);
  DoneCollector collector;
  FakeBlackboard blackboard;
  blackboard.lcm = &lcm;
  lcm.subscribe(channels::kDone, &DoneCollector::onDone, &collector);
  lcm.subscribe(channels::kBlackboardQuery, &FakeBlackboard::onQuery, &blackboard);
  std::thread runner([&] { expert::runLive(reader, options); });
  // Its catch-up query (sent once it listens) finds nothing.
  EXPECT_TRUE(pumpUntil(lcm, [&] { return blackboard.queries.load() >= 1; }));
  const int catch_up_queries = blackboard.queries.load();
  const auto fire = fireToken("reader", 6, 1);
  lcm.publish(channels::kFire, &fire);  // tick 6: the blackboard holds only tick 5
  EXPECT_TRUE(pumpUntil(lcm, [&] { return blackboard.queries.load() > catch_up_queries; }))
      << "never asked the blackboard again";
  const auto fire5 = fireToken("reader", 5, 2);
  lcm.publish(channels::kFire, &fire5);  // tick 5: lost live, held by the blackboard
  // Firing 1's DONE, had it fired without its input, would come before this one.
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 1; }));
  beft::run_status_t end{};
  end.state = beft::run_status_t::STATE_FINISHED;
  lcm.publish(channels::kRunStatus, &end);
  runner.join();

  std::lock_guard<std::mutex> lock(collector.mutex);
  ASSERT_EQ(collector.done.size(), 1u);
  EXPECT_EQ(collector.done[0].firing_id, 2) << "fired without the input of its tick";
  EXPECT_EQ(collector.done[0].outcome, beft::done_t::OUTCOME_OK) << collector.done[0].message;
}

TEST(LiveRunner, AnInputArrivingAfterItsFireIsWaitedFor) {
  // On udpm an expert's inputs and its FIREs come on two sockets; across
  // machines the FIRE may come first. With LCM's own receive thread
  // (BEFT_UDPM_RECEIVER=0) both come through one subscription.
  for (const bool direct : {true, false}) {
    if (!direct) setenv("BEFT_UDPM_RECEIVER", "0", 1);
    ScalingExpert scaler;
    scaler.startUp();
    expert::LiveOptions options = scalerOptions(direct ? 3 : 4);
    options.heartbeat_period_s = 0.05;
    const std::string url = options.lcm_url;
    lcm::LCM lcm(url);
    DoneCollector collector;
    lcm.subscribe(channels::kDone, &DoneCollector::onDone, &collector);
    lcm.subscribe("SCALED", &DoneCollector::onScaled, &collector);
    lcm.subscribe(channels::kHeartbeat, &DoneCollector::onHeartbeat, &collector);
    std::thread runner([&] { expert::runLive(scaler, options); });

    EXPECT_TRUE(waitUntilListening(lcm, collector));
    const auto early = stateAt(6, 1.0);  // before the FIRE, as on one machine
    lcm.publish(channels::kRobotState, &early);
    const auto fire6 = fireToken("scaler", 6, 1);
    lcm.publish(channels::kFire, &fire6);
    EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 1; }));
    const auto fire7 = fireToken("scaler", 7, 2);
    lcm.publish(channels::kFire, &fire7);
    // A beat saying "waiting" (for its inputs) after firing 1 finished: FIRE 7 has arrived.
    EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.lastBeatIs("waiting", 1); }));
    const auto late = stateAt(7, 4.0);  // after its FIRE
    lcm.publish(channels::kRobotState, &late);
    EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 2; }));
    beft::run_status_t end{};
    end.state = beft::run_status_t::STATE_FINISHED;
    lcm.publish(channels::kRunStatus, &end);
    runner.join();
    unsetenv("BEFT_UDPM_RECEIVER");

    std::lock_guard<std::mutex> lock(collector.mutex);
    ASSERT_EQ(collector.done.size(), 2u) << (direct ? "direct" : "LCM");
    for (const auto& done : collector.done) EXPECT_EQ(done.outcome, beft::done_t::OUTCOME_OK) << done.message;
    ASSERT_EQ(collector.scaled.size(), 2u);
    EXPECT_DOUBLE_EQ(collector.scaled[0].x, 2.0);
    EXPECT_DOUBLE_EQ(collector.scaled[1].x, 8.0) << "fired with the state that came after its FIRE";
    EXPECT_EQ(scaler.fires.load(), 2);
  }
}

TEST(Ports, ReadsWritesAndDispatchComeFromTheDeclaredPorts) {
  ScalingExpert scaler;
  ASSERT_EQ(scaler.reads().size(), 1u);
  EXPECT_EQ(scaler.reads()[0].channel, "ROBOT_STATE");
  EXPECT_EQ(scaler.reads()[0].type, "beft.robot_state_t");
  ASSERT_EQ(scaler.writes().size(), 1u);
  EXPECT_EQ(scaler.writes()[0].channel, "SCALED");
  EXPECT_EQ(scaler.writes()[0].type, "beft.robot_state_t");
  const auto state = stateAt(3, 1.5);
  std::vector<uint8_t> bytes(state.getEncodedSize());
  state.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  EXPECT_TRUE(scaler.onMessage("ROBOT_STATE", bytes.data(), static_cast<int>(bytes.size())));
  EXPECT_FALSE(scaler.onMessage("GT_OBJECTS", bytes.data(), static_cast<int>(bytes.size()))) << "no port reads it";
  EXPECT_FALSE(scaler.onMessage("ROBOT_STATE", bytes.data(), 5)) << "not a robot_state_t";
  EXPECT_TRUE(scaler.inputsReady({"scaler", "t", 3, 300000, 1}));
}

TEST(Ports, PublishingOnAnUndeclaredChannelFails) {
  struct Sink : expert::Output {
    std::vector<std::string> channels;
    void publishEncoded(const std::string& channel, const std::vector<uint8_t>&) override {
      channels.push_back(channel);
    }
  } sink;
  ScalingExpert scaler;
  sink.restrictTo(scaler.writes());
  sink.publish(kScaled, stateAt(1, 1));
  EXPECT_THROW(sink.publish(channels::kRobotState, stateAt(1, 1)), std::logic_error);
  EXPECT_EQ(sink.channels, std::vector<std::string>{"SCALED"});
}

TEST(Parameters, DeclaredOnceWithDefaultRangeAndMeaning) {
  ScalingExpert scaler;
  const auto& list = scaler.parameters().list();
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0].name, "factor");
  EXPECT_EQ(list[0].default_value, "2");
  EXPECT_EQ(list[0].range, "[0, 100]");
  EXPECT_NE(scaler.parameters().describe().find("factor (default 2, [0, 100]): scale of x"), std::string::npos);
}

TEST(Parameters, OutOfRangeAndUnknownAreRefusedWithTheRange) {
  ScalingExpert scaler;
  try {
    scaler.startUp({{"factor", "250"}});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("factor='250' is not [0, 100]"), std::string::npos) << e.what();
  }
  EXPECT_THROW(scaler.startUp({{"factor", "x1"}}), std::invalid_argument);
  try {
    scaler.startUp({{"gain", "2"}});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown parameter 'gain' (known: factor)"), std::string::npos) << e.what();
  }
}

TEST(Parameters, EachStartUpBeginsFromTheDefaults) {
  DeclaredParameters declared;
  double gain = 2.5;
  int count = 7;
  bool flag = false;
  std::string word = "a";
  declared.declare("gain", gain, 0, 10, "g", true);
  declared.declare("count", count, 1, 9, "c");
  declared.declare("flag", flag, "f");
  declared.declare("word", word, "w");
  declared.setAll({{"gain", "4"}, {"count", "3"}, {"flag", "yes"}, {"word", "b"}});
  EXPECT_DOUBLE_EQ(gain, 4);
  EXPECT_EQ(count, 3);
  EXPECT_TRUE(flag);
  EXPECT_EQ(word, "b");
  EXPECT_EQ(declared.current("count"), "3");
  EXPECT_THROW(declared.set("gain", "0"), std::invalid_argument) << "(0, 10] excludes 0";
  EXPECT_THROW(declared.set("count", "2.5"), std::invalid_argument);
  EXPECT_THROW(declared.set("flag", "maybe"), std::invalid_argument);
  declared.resetToDefaults();
  EXPECT_DOUBLE_EQ(gain, 2.5);
  EXPECT_EQ(count, 7);
  EXPECT_FALSE(flag);
  EXPECT_EQ(word, "a");
  EXPECT_THROW(declared.declare("gain", gain, 0, 1, "again"), std::logic_error);
}

namespace {
// A log as a run would record it: inputs, FIRE (sent twice), DONE, outputs.
std::string writeRecordedLog(double recorded_factor, int64_t lost_tick = -1) {
  char path[] = "/tmp/beft_replay_XXXXXX";
  const int fd = mkstemp(path);
  close(fd);
  lcm::LogFile log(path, "w");
  int64_t event_number = 0;
  auto write = [&](const std::string& channel, const auto& message) {
    std::vector<uint8_t> bytes(message.getEncodedSize());
    message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    lcm::LogEvent event;
    event.eventnum = event_number++;
    event.timestamp = event_number * 1000;
    event.channel = channel;
    event.datalen = static_cast<int32_t>(bytes.size());
    event.data = bytes.data();
    log.writeEvent(&event);
  };
  for (int64_t tick = 0; tick < 5; ++tick) {
    write(channels::kRobotState, stateAt(tick, 1.0 + tick));
    const auto fire = fireToken("scaler", tick, 100 + tick);
    write(channels::kFire, fire);
    write(channels::kFire, fire);
    auto out = stateAt(tick, (1.0 + tick) * recorded_factor);
    if (tick != lost_tick) write("SCALED", out);  // a datagram the logger lost
  }
  return path;
}
}  // namespace

TEST(Replay, SameParametersMatchExactly) {
  const std::string log_path = writeRecordedLog(2.0);
  ScalingExpert scaler;
  scaler.startUp();
  const auto result = expert::replayLog(scaler, "scaler", log_path);
  EXPECT_EQ(result.firings, 5);
  EXPECT_EQ(result.outputs_compared, 5);
  EXPECT_TRUE(result.exactMatch());
  std::remove(log_path.c_str());
}

TEST(Replay, ChangedParameterShowsTheDifference) {
  const std::string log_path = writeRecordedLog(2.0);
  ScalingExpert scaler;
  scaler.startUp({{"factor", "3"}});
  const auto result = expert::replayLog(scaler, "scaler", log_path);
  EXPECT_EQ(result.firings, 5);
  EXPECT_FALSE(result.exactMatch());
  EXPECT_EQ(result.outputs_matching, 0);
  ASSERT_FALSE(result.first_mismatches.empty());
  EXPECT_EQ(result.first_mismatches[0].channel, "SCALED");
  EXPECT_EQ(result.first_mismatches[0].index, 100);  // the firing it belongs to
  std::remove(log_path.c_str());
}

TEST(Replay, AnOutputLostByTheLoggerShiftsNothing) {
  const std::string log_path = writeRecordedLog(2.0, 1);
  ScalingExpert scaler;
  scaler.startUp();
  const auto result = expert::replayLog(scaler, "scaler", log_path);
  EXPECT_EQ(result.outputs_compared, 4);
  EXPECT_EQ(result.outputs_matching, 4);
  EXPECT_EQ(result.replayed_only, 1);
  EXPECT_TRUE(result.exactMatch());
  std::remove(log_path.c_str());
}

// A process killed between an output and its DONE: restarted, it runs that
// firing again, and what the log holds of it is not to be sent twice.
TEST(Resume, TheOutputsOfTheFiringInFlightAreKnownAsSentAlready) {
  const std::string log_path = writeRecordedLog(2.0);  // no DONE: the last FIRE is in flight
  ScalingExpert scaler;
  scaler.startUp();
  const auto state = expert::resumeFromLog(scaler, "scaler", log_path, 0);
  ASSERT_TRUE(state.in_flight);
  EXPECT_EQ(state.in_flight->firing_id, 104);
  const auto sent = stateAt(4, 5.0 * 2.0);
  std::vector<uint8_t> bytes(sent.getEncodedSize());
  sent.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  EXPECT_EQ(state.in_flight_outputs.size(), 1u);
  EXPECT_EQ(state.in_flight_outputs.count(expert::messageFingerprint("SCALED", bytes.data(), bytes.size())), 1u);
  std::remove(log_path.c_str());
}

TEST(Resume, AFiringInFlightThatPublishedNothingOwesNothing) {
  const std::string log_path = writeRecordedLog(2.0, 4);  // the last firing's output never made it
  ScalingExpert scaler;
  scaler.startUp();
  const auto state = expert::resumeFromLog(scaler, "scaler", log_path, 0);
  ASSERT_TRUE(state.in_flight);
  EXPECT_TRUE(state.in_flight_outputs.empty());
  std::remove(log_path.c_str());
}

TEST(Replay, MissingLogIsAClearError) {
  ScalingExpert scaler;
  try {
    expert::replayLog(scaler, "scaler", "/nonexistent/run.lcmlog");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/run.lcmlog"), std::string::npos);
  }
}

namespace {
// Declares its inputs and nothing more: whether a firing may run comes from
// the framework (no inputsReady of its own).
class DeclaredInputsOnly : public expert::Expert {
 public:
  std::string name() const override { return "declared"; }
  std::string description() const override { return "test expert"; }
  expert::Outcome fire(const expert::Firing& f, expert::Output&) override {
    fires.fetch_add(1);
    return robot_.has(f.tick) ? expert::Outcome::success() : expert::Outcome::failure("fired without its input");
  }
  void keep(const beft::robot_state_t& state) { robot_.store(state); }
  std::atomic<int> fires{0};

 private:
  expert::TickInput<beft::robot_state_t> robot_{*this, channels::kRobotState};
  // Needed only once one was heard (older logs lack it).
  expert::TickInput<beft::robot_state_t> optional_{*this, kScaled, 16, {}, /*optional_until_heard=*/true};
};
}  // namespace

TEST(Ports, WithoutAnOverrideAFiringWaitsForEveryDeclaredTickInput) {
  DeclaredInputsOnly expert;
  const expert::Firing tick3{"declared", "t", 3, 300000, 1};
  EXPECT_FALSE(expert.inputsReady(tick3)) << "nothing heard yet";
  expert.keep(stateAt(2, 1.0));
  EXPECT_FALSE(expert.inputsReady(tick3)) << "only the previous tick's";
  expert.keep(stateAt(3, 1.0));
  EXPECT_TRUE(expert.inputsReady(tick3)) << "the optional input was never heard";
  EXPECT_EQ(expert.inputsLacking(tick3), std::vector<std::string>{});
}

namespace {
// Reads the hypotheses and a second robot state only with --param listen=1.
class ConfiguredInputs : public expert::Expert {
 public:
  std::string name() const override { return "configured"; }
  std::string description() const override { return "test expert"; }
  expert::Outcome fire(const expert::Firing&, expert::Output&) override { return expert::Outcome::success(); }
  void keep(const beft::robot_state_t& state) { robot_.store(state); }

 protected:
  void declareParameters(DeclaredParameters& parameters) override {
    parameters.declare("listen", listen_, "1: read the hypotheses and SCALED too");
  }
  void onStartUp() override {
    hypotheses_.setRead(listen_);
    scaled_.setRead(listen_);
  }

 private:
  bool listen_ = false;
  expert::TickInput<beft::robot_state_t> robot_{*this, channels::kRobotState};
  expert::HypothesesInput hypotheses_{*this};
  expert::TickInput<beft::robot_state_t> scaled_{*this, kScaled};
};

std::vector<std::string> channelsOf(const std::vector<expert::ChannelSpec>& specs) {
  std::vector<std::string> names;
  for (const auto& spec : specs) names.push_back(spec.channel);
  return names;
}
}  // namespace

TEST(Ports, AnInputSwitchedOffAtStartUpIsNeitherReadNorWaitedFor) {
  ConfiguredInputs expert;
  const std::vector<std::string> all{"ROBOT_STATE", "HYPOTHESES", "HYPOTHESIS_CHANGES", "SCALED"};
  EXPECT_EQ(channelsOf(expert.reads()), all) << "before start-up (--interface) every port is listed";
  const auto state = stateAt(3, 1.0);
  std::vector<uint8_t> bytes(state.getEncodedSize());
  state.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  const expert::Firing tick3{"configured", "t", 3, 300000, 1};

  expert.startUp({{"listen", "0"}});
  EXPECT_EQ(channelsOf(expert.reads()), std::vector<std::string>{"ROBOT_STATE"})
      << "the hypotheses port leaves with both its channels";
  EXPECT_FALSE(expert.onMessage("SCALED", bytes.data(), static_cast<int>(bytes.size()))) << "not kept";
  expert.keep(state);
  EXPECT_TRUE(expert.inputsReady(tick3)) << "SCALED is not waited for";
  EXPECT_TRUE(expert.inputsLacking(tick3).empty());

  expert.startUp({{"listen", "1"}});
  EXPECT_EQ(channelsOf(expert.reads()), all) << "each start-up begins with every port read";
  EXPECT_FALSE(expert.inputsReady(tick3)) << "SCALED of tick 3 is missing";
  EXPECT_EQ(expert.inputsLacking(tick3), std::vector<std::string>{"SCALED"});
  EXPECT_TRUE(expert.onMessage("SCALED", bytes.data(), static_cast<int>(bytes.size())));
  EXPECT_TRUE(expert.inputsReady(tick3));
}

TEST(LiveRunner, WithoutAnOverrideAFiringLackingItsTickInputDoesNotFire) {
  DeclaredInputsOnly expert;
  expert.startUp();
  expert::LiveOptions options = scalerOptions(5);
  options.process_name = "declared";
  options.ready_timeout_s = 0;  // wait as long as it takes
  options.heartbeat_period_s = 0.05;
  lcm::LCM lcm(options.lcm_url);
  DoneCollector collector;
  lcm.subscribe(channels::kDone, &DoneCollector::onDone, &collector);
  lcm.subscribe(channels::kHeartbeat, &DoneCollector::onHeartbeat, &collector);
  std::thread runner([&] { expert::runLive(expert, options); });
  EXPECT_TRUE(waitUntilListening(lcm, collector));
  const auto previous = stateAt(5, 1.0);
  lcm.publish(channels::kRobotState, &previous);
  const auto fire = fireToken("declared", 6, 1);
  lcm.publish(channels::kFire, &fire);
  // A beat saying "waiting" with no firing done yet: FIRE 6 has arrived and waits for its input.
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.lastBeatIs("waiting", -1); }));
  EXPECT_EQ(expert.fires.load(), 0) << "fired without the ROBOT_STATE of its tick";
  EXPECT_EQ(collector.doneCount(), 0u);
  const auto own = stateAt(6, 2.0);
  lcm.publish(channels::kRobotState, &own);
  EXPECT_TRUE(pumpUntil(lcm, [&] { return collector.doneCount() >= 1; }));
  beft::run_status_t end{};
  end.state = beft::run_status_t::STATE_FINISHED;
  lcm.publish(channels::kRunStatus, &end);
  runner.join();

  std::lock_guard<std::mutex> lock(collector.mutex);
  ASSERT_EQ(collector.done.size(), 1u);
  EXPECT_EQ(collector.done[0].outcome, beft::done_t::OUTCOME_OK) << collector.done[0].message;
  EXPECT_EQ(expert.fires.load(), 1);
}

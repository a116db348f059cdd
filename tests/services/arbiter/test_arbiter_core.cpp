// The arbiter core against scripted mock experts, on a simulated clock:
// order of firings, lost and duplicate messages, every policy, dead experts,
// deadlocks, start-up and the end of a run.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <string>
#include <vector>

#include "services/arbiter/arbiter_core.hpp"
#include "lib/petri/pnml_reader.hpp"

namespace beft::arbiter {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
const std::string kNets = std::string(BEFT_SOURCE_DIR) + "/scenarios/nets/";

class FakeClock : public Clock {
 public:
  double now() const override { return t; }
  double t = 0.0;
};

// What a mock expert does; every hook may be left empty.
struct Script {
  std::function<double(const beft::fire_t&)> duration;          // seconds; < 0: drops the firing
  std::function<bool(const beft::fire_t&, int arrival)> lose_fire;  // arrival: 0 for the first copy
  std::function<bool(const beft::done_t&, int send)> lose_done;     // send: 0 for the first DONE
  std::function<bool(const beft::fire_t&)> fails;                // answers OUTCOME_FAILED
  std::function<int(const beft::fire_t&)> done_copies;           // DONE sent this many times
  double starts_at = 0.0;          // first heartbeat
  double dies_at = kNever;         // silent from then on
  int64_t reported_firing_id = -1; // last_firing_id in its heartbeats before it runs anything
  bool waits_for_inputs = false;   // its heartbeats say "waiting" while it runs a firing
};

// One entry of the protocol as seen by the arbiter: a new firing id sent, or a firing ended.
struct Entry {
  double time;
  char kind;  // 'F' first FIRE of an id, 'D' DONE accepted, 'S' skipped, 'R' retried, 'X' failed run
  std::string expert;
  int64_t tick;
  int64_t firing_id;
};

// A discrete-event simulation of the experts around the core.
class Simulation : public ArbiterOutput {
 public:
  Simulation(Net net, ArbiterConfig config) : core_(std::move(net), config, clock_, *this) {}

  Script& expert(const std::string& name) { return scripts_[name]; }
  // A process outside the net (a service such as the planner) that sends
  // heartbeats from `starts_at` on.
  void service(const std::string& name, double starts_at) { services_[name] = starts_at; }

  // Runs until the core is done (or `until` simulated seconds).
  void run(double until = 600.0) {
    for (const auto& name : core_.net().experts()) {
      scripts_[name];  // every expert of the net exists, with the default script
      scheduleHeartbeat(name, scripts_[name].starts_at);
    }
    for (const auto& [name, starts_at] : services_) {
      scripts_[name].starts_at = starts_at;  // its heartbeats only: it is never fired
      scheduleHeartbeat(name, starts_at);
    }
    core_.start();
    for (int iterations = 0; !core_.done() && iterations < 10000000; ++iterations) {
      const double next_event = events_.empty() ? kNever : events_.top().time;
      const double deadline = core_.nextDeadline();
      const double next = std::min(next_event, deadline);
      if (next == kNever || next > until) break;
      clock_.t = std::max(clock_.t, next);
      if (next_event <= deadline) {
        const auto action = events_.top().action;
        events_.pop();
        action();
      } else {
        core_.onTimeAdvanced();
      }
    }
  }

  // Delivers a DONE to the core at the current simulated time.
  void inject(const beft::done_t& done) { core_.onDone(done); }
  void at(double time, std::function<void()> action) { schedule(time, std::move(action)); }

  ArbiterCore& core() { return core_; }
  double now() const { return clock_.t; }
  const std::vector<Entry>& entries() const { return entries_; }
  const std::vector<beft::fire_t>& fires() const { return fires_; }
  const std::vector<beft::marking_t>& markings() const { return markings_; }
  const std::vector<beft::run_status_t>& statuses() const { return statuses_; }
  const std::vector<FiringRecord>& records() const { return records_; }
  // Times the expert's fire() ran for that tick (the protocol promises once).
  int runs(const std::string& expert, int64_t tick) const {
    const auto it = runs_.find({expert, tick});
    return it == runs_.end() ? 0 : it->second;
  }
  int firesLost() const { return fires_lost_; }
  int donesLost() const { return dones_lost_; }

  // ArbiterOutput
  void sendFire(const beft::fire_t& fire) override {
    fires_.push_back(fire);
    if (announced_.insert(fire.firing_id).second)
      entries_.push_back({clock_.t, 'F', fire.expert, fire.tick, fire.firing_id});
    const int arrival = arrivals_[fire.firing_id]++;
    const Script& script = scripts_[fire.expert];
    if (script.lose_fire && script.lose_fire(fire, arrival)) {
      ++fires_lost_;
      return;
    }
    schedule(clock_.t + kLatency, [this, fire] { expertReceives(fire); });
  }
  void sendMarking(const beft::marking_t& marking) override { markings_.push_back(marking); }
  void sendRunStatus(const beft::run_status_t& status) override { statuses_.push_back(status); }
  void firingEnded(const FiringRecord& record) override {
    records_.push_back(record);
    const char kind = record.action.empty() ? (record.outcome == "ok" ? 'D' : 'A')
                      : record.action == "skip"  ? 'S'
                      : record.action == "retry" ? 'R'
                                                 : 'X';
    entries_.push_back({clock_.t, kind, record.expert, record.tick, record.firing_id});
  }

 private:
  static constexpr double kLatency = 0.0002;
  static constexpr double kHeartbeatPeriod = 0.5;

  struct MockExpert {
    int64_t highest_seen = 0;
    int64_t running = -1;
    std::optional<beft::fire_t> queued;  // arrived while busy
    std::optional<beft::done_t> last_done;
    int64_t last_finished = -1;
    std::map<int64_t, int> done_sends;
  };

  struct Event {
    double time;
    int64_t order;
    std::function<void()> action;
    bool operator<(const Event& other) const {  // for a min-heap
      return time != other.time ? time > other.time : order > other.order;
    }
  };

  void schedule(double time, std::function<void()> action) {
    events_.push(Event{time, next_order_++, std::move(action)});
  }

  bool alive(const std::string& name) const {
    const Script& script = scripts_.at(name);
    return clock_.t >= script.starts_at && clock_.t < script.dies_at;
  }

  void scheduleHeartbeat(const std::string& name, double time) {
    schedule(time, [this, name] {
      if (clock_.t >= scripts_[name].dies_at) return;
      beft::heartbeat_t beat{};
      beat.process = name;
      beat.pid = 1;
      beat.host = "sim";
      const MockExpert& mock = mocks_[name];
      beat.last_firing_id = mock.last_finished >= 0 ? mock.last_finished : scripts_[name].reported_firing_id;
      beat.state = mock.running < 0 ? "idle" : scripts_[name].waits_for_inputs ? "waiting" : "firing";
      schedule(clock_.t + kLatency, [this, beat] { core_.onHeartbeat(beat); });
      scheduleHeartbeat(name, clock_.t + kHeartbeatPeriod);
    });
  }

  // The expert side of the protocol, as the expert runner implements it.
  void expertReceives(const beft::fire_t& fire) {
    if (!alive(fire.expert)) return;
    MockExpert& mock = mocks_[fire.expert];
    if (fire.firing_id == mock.last_finished) {  // a re-send: answer again, never run again
      sendDone(fire.expert, *mock.last_done);
      return;
    }
    if (fire.firing_id <= mock.highest_seen) return;  // stale, or the one running now
    mock.highest_seen = fire.firing_id;
    if (mock.running >= 0) {
      mock.queued = fire;
      return;
    }
    startRun(fire);
  }

  void startRun(const beft::fire_t& fire) {
    MockExpert& mock = mocks_[fire.expert];
    const Script& script = scripts_[fire.expert];
    const double duration = script.duration ? script.duration(fire) : 0.001;
    if (duration < 0.0) return;  // lost inside the expert: never answered
    mock.running = fire.firing_id;
    schedule(clock_.t + duration, [this, fire] { finishRun(fire); });
  }

  void finishRun(const beft::fire_t& fire) {
    if (!alive(fire.expert)) return;
    MockExpert& mock = mocks_[fire.expert];
    const Script& script = scripts_[fire.expert];
    ++runs_[{fire.expert, fire.tick}];
    beft::done_t done{};
    done.utime = fire.utime;
    done.expert = fire.expert;
    done.tick = fire.tick;
    done.firing_id = fire.firing_id;
    const bool failed = script.fails && script.fails(fire);
    done.outcome = failed ? beft::done_t::OUTCOME_FAILED : beft::done_t::OUTCOME_OK;
    done.message = failed ? "scripted failure" : "";
    mock.running = -1;
    mock.last_finished = fire.firing_id;
    mock.last_done = done;
    const int copies = script.done_copies ? script.done_copies(fire) : 1;
    for (int i = 0; i < copies; ++i) sendDone(fire.expert, done);
    if (mock.queued) {
      const beft::fire_t next = *mock.queued;
      mock.queued.reset();
      startRun(next);
    }
  }

  void sendDone(const std::string& name, const beft::done_t& done) {
    const int send = mocks_[name].done_sends[done.firing_id]++;
    const Script& script = scripts_[name];
    if (script.lose_done && script.lose_done(done, send)) {
      ++dones_lost_;
      return;
    }
    schedule(clock_.t + kLatency, [this, done] { core_.onDone(done); });
  }

  FakeClock clock_;
  ArbiterCore core_;
  std::map<std::string, Script> scripts_;
  std::map<std::string, double> services_;  // outside the net: name -> first heartbeat
  std::map<std::string, MockExpert> mocks_;
  std::priority_queue<Event> events_;
  int64_t next_order_ = 0;
  std::set<int64_t> announced_;
  std::map<int64_t, int> arrivals_;
  std::map<std::pair<std::string, int64_t>, int> runs_;
  std::vector<Entry> entries_;
  std::vector<beft::fire_t> fires_;
  std::vector<beft::marking_t> markings_;
  std::vector<beft::run_status_t> statuses_;
  std::vector<FiringRecord> records_;
  int fires_lost_ = 0, dones_lost_ = 0;
};

// Position in the protocol sequence of an entry (kind, expert, tick); -1 if absent.
int positionOf(const std::vector<Entry>& entries, char kind, const std::string& expert, int64_t tick) {
  for (size_t i = 0; i < entries.size(); ++i)
    if (entries[i].kind == kind && entries[i].expert == expert && entries[i].tick == tick)
      return static_cast<int>(i);
  return -1;
}

int countOf(const std::vector<Entry>& entries, char kind, const std::string& expert, int64_t tick) {
  return static_cast<int>(std::count_if(entries.begin(), entries.end(), [&](const Entry& e) {
    return e.kind == kind && e.expert == expert && e.tick == tick;
  }));
}

// Firings of the paper's schedule happen in its order, checked from the
// FIRE/DONE sequence: world, then low together, then mid together, then high
// one after the other; `levels` lists the stages of the net.
void expectStagedOrder(const std::vector<Entry>& entries, const std::vector<std::vector<std::string>>& stages,
                       int64_t ticks) {
  for (int64_t k = 0; k < ticks; ++k) {
    for (size_t s = 0; s < stages.size(); ++s) {
      int first_fire = INT32_MAX, last_fire = -1, first_done = INT32_MAX, last_done = -1;
      for (const auto& expert : stages[s]) {
        const int fire = positionOf(entries, 'F', expert, k);
        const int done = positionOf(entries, 'D', expert, k);
        ASSERT_GE(fire, 0) << expert << " never fired in tick " << k;
        ASSERT_GE(done, 0) << expert << " never finished in tick " << k;
        EXPECT_EQ(countOf(entries, 'F', expert, k), 1) << expert << " tick " << k;
        EXPECT_EQ(countOf(entries, 'D', expert, k), 1) << expert << " tick " << k;
        first_fire = std::min(first_fire, fire);
        last_fire = std::max(last_fire, fire);
        first_done = std::min(first_done, done);
        last_done = std::max(last_done, done);
      }
      // A stage starts all its experts before any of them finishes (they run together).
      EXPECT_LT(last_fire, first_done) << "stage " << s << " tick " << k;
      // The next stage starts only when all of this one are done.
      const bool last_stage = s + 1 == stages.size();
      const auto& next = last_stage ? stages[0] : stages[s + 1];
      const int64_t next_tick = last_stage ? k + 1 : k;
      if (next_tick >= ticks) continue;
      for (const auto& expert : next)
        EXPECT_LT(last_done, positionOf(entries, 'F', expert, next_tick))
            << expert << " fired before stage " << s << " of tick " << k << " was done";
    }
  }
}

const std::vector<std::vector<std::string>> kDefaultStages = {
    {"world"}, {"geometry", "vision", "audio"}, {"visual_labels", "acoustic_labels"},
    {"fusion"}, {"dw"}, {"exploration"}, {"tasks"}};

// Durations that differ by expert and tick, so the concurrent ones finish in varying orders.
double variedDuration(const beft::fire_t& fire) {
  const size_t h = std::hash<std::string>{}(fire.expert) + static_cast<size_t>(fire.tick) * 7;
  return 0.001 * static_cast<double>(1 + h % 5);
}

ArbiterConfig testConfig(int64_t ticks) {
  ArbiterConfig config;
  config.max_ticks = ticks;
  config.dt_s = 0.1;
  config.resend_period_s = 0.02;  // the simulated latencies below are sized to it
  config.heartbeat_timeout_s = 1.0;
  return config;
}

// A chain of experts, one after the other, each with its policy options.
Net chainNet(const std::vector<std::pair<std::string, std::string>>& experts) {
  std::string text = "<pnml><net id=\"chain\"><place id=\"p0\"><initialMarking><text>1</text></initialMarking></place>";
  for (size_t i = 0; i < experts.size(); ++i) {
    const std::string& name = experts[i].first;
    text += "<place id=\"p" + std::to_string(i + 1) + "\"/>";
    text += "<transition id=\"t_" + name + "\"><toolspecific tool=\"beft\" version=\"1\"><expert>" + name +
            "</expert>" + experts[i].second + "</toolspecific></transition>";
    text += "<arc id=\"in_" + name + "\" source=\"p" + std::to_string(i) + "\" target=\"t_" + name + "\"/>";
    text += "<arc id=\"out_" + name + "\" source=\"t_" + name + "\" target=\"p" + std::to_string(i + 1) + "\"/>";
  }
  text += "<transition id=\"t_tick\"><toolspecific tool=\"beft\"><tick/></toolspecific></transition>";
  text += "<arc id=\"tick_in\" source=\"p" + std::to_string(experts.size()) + "\" target=\"t_tick\"/>";
  text += "<arc id=\"tick_out\" source=\"t_tick\" target=\"p0\"/></net></pnml>";
  return readPnmlString(text, "chain.pnml");
}

bool contains(const std::string& text, const std::string& fragment) {
  return text.find(fragment) != std::string::npos;
}

TEST(ArbiterCore, FollowsTheDefaultNetOrder) {
  const int64_t ticks = 5;
  Simulation sim(readPnmlFile(kNets + "default.pnml"), testConfig(ticks));
  for (const auto& stage : kDefaultStages)
    for (const auto& name : stage) sim.expert(name).duration = variedDuration;
  sim.run();

  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  EXPECT_EQ(sim.core().message(), "finished after 5 ticks");
  EXPECT_EQ(sim.core().stats().ticks_completed, ticks);
  expectStagedOrder(sim.entries(), kDefaultStages, ticks);
  for (const auto& stage : kDefaultStages)
    for (const auto& name : stage)
      for (int64_t k = 0; k < ticks; ++k) EXPECT_EQ(sim.runs(name, k), 1) << name << " tick " << k;
  EXPECT_EQ(positionOf(sim.entries(), 'F', "world", ticks), -1);  // nothing of a sixth tick

  // Firing ids only grow, FIRE carries utime = tick * dt.
  int64_t previous = 0;
  for (const auto& fire : sim.fires()) {
    EXPECT_GE(fire.firing_id, previous);
    previous = fire.firing_id;
    EXPECT_EQ(fire.utime, fire.tick * 100000);
  }
  // No message was lost, so no FIRE was re-sent (durations are far below the period).
  EXPECT_EQ(sim.fires().size(), 10u * ticks);

  // RUN_STATUS: running for ticks 0..4, then FINISHED repeated.
  std::vector<std::string> running;
  int finished = 0;
  for (const auto& status : sim.statuses()) {
    if (status.state == beft::run_status_t::STATE_RUNNING) running.push_back(status.message);
    if (status.state == beft::run_status_t::STATE_FINISHED) ++finished;
  }
  EXPECT_EQ(running, (std::vector<std::string>{"tick 0", "tick 1", "tick 2", "tick 3", "tick 4"}));
  EXPECT_EQ(finished, ArbiterConfig{}.final_status_repeats);

  // MARKING after every step: one per DONE plus the start; always 1-safe.
  EXPECT_EQ(sim.markings().size(), 1u + 10 * ticks);
  for (size_t i = 0; i < sim.markings().size(); ++i) {
    const auto& m = sim.markings()[i];
    EXPECT_EQ(m.step, static_cast<int64_t>(i) + 1);
    for (int32_t tokens : m.tokens) EXPECT_LE(tokens, 1);
  }
  const auto& last = sim.markings().back();
  const size_t tick_end = std::find(last.place_ids.begin(), last.place_ids.end(), "p_tick_end") - last.place_ids.begin();
  ASSERT_LT(tick_end, last.place_ids.size());
  EXPECT_EQ(last.tokens[tick_end], 1);
  EXPECT_TRUE(contains(sim.markings()[0].event, "fire world"));
  // A marking while the low level runs lists the three experts.
  const auto low = std::find_if(sim.markings().begin(), sim.markings().end(),
                                [](const beft::marking_t& m) { return m.num_running == 3; });
  ASSERT_NE(low, sim.markings().end());
  EXPECT_EQ(low->running, (std::vector<std::string>{"vision", "geometry", "audio"}));
}

TEST(ArbiterCore, SequentialNetRunsOneExpertAtATime) {
  const int64_t ticks = 3;
  Simulation sim(readPnmlFile(kNets + "sequential.pnml"), testConfig(ticks));
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  for (const auto& m : sim.markings()) EXPECT_LE(m.num_running, 1);
  expectStagedOrder(sim.entries(),
                    {{"world"}, {"geometry"}, {"vision"}, {"audio"}, {"visual_labels"}, {"acoustic_labels"},
                     {"fusion"}, {"dw"}, {"exploration"}, {"tasks"}},
                    ticks);
}

TEST(ArbiterCore, ConcurrentNetStartsEachExpertWhenWhatItReadsIsDone) {
  const int64_t ticks = 3;
  Simulation sim(readPnmlFile(kNets + "concurrent.pnml"), testConfig(ticks));
  sim.expert("vision").duration = [](const beft::fire_t&) { return 0.050; };  // the long one, as in a run
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  const auto& entries = sim.entries();
  // Each expert after the ones whose output it reads, and nothing more.
  const std::map<std::string, std::vector<std::string>> after = {
      {"geometry", {"world"}}, {"vision", {"world"}}, {"audio", {"world"}},
      {"visual_labels", {"vision", "geometry"}}, {"acoustic_labels", {"audio", "geometry"}},
      {"dw", {"acoustic_labels"}}, {"fusion", {"visual_labels", "acoustic_labels"}},
      {"exploration", {"fusion", "dw"}}, {"tasks", {"exploration"}}};
  for (int64_t k = 0; k < ticks; ++k) {
    for (const auto& [expert, inputs] : after) {
      ASSERT_EQ(countOf(entries, 'F', expert, k), 1) << expert << " tick " << k;
      for (const auto& input : inputs)
        EXPECT_LT(positionOf(entries, 'D', input, k), positionOf(entries, 'F', expert, k))
            << expert << " started before " << input << " was done in tick " << k;
    }
    // Acoustic labels and dynamic weighting no longer wait for vision.
    EXPECT_LT(positionOf(entries, 'D', "dw", k), positionOf(entries, 'D', "vision", k)) << "tick " << k;
    if (k > 0) {
      EXPECT_LT(positionOf(entries, 'D', "tasks", k - 1), positionOf(entries, 'F', "world", k));
    }
  }
}

TEST(ArbiterCore, RecoversALostFireByResending) {
  Simulation sim(readPnmlFile(kNets + "experts_only.pnml"), testConfig(3));
  // The first three copies of vision's FIRE in tick 1 are lost.
  sim.expert("vision").lose_fire = [](const beft::fire_t& f, int arrival) { return f.tick == 1 && arrival < 3; };
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  EXPECT_EQ(sim.firesLost(), 3);
  EXPECT_EQ(sim.core().stats().fire_resends, 3);
  EXPECT_EQ(sim.runs("vision", 1), 1);
  EXPECT_EQ(countOf(sim.entries(), 'F', "vision", 1), 1);  // re-sent with the same id
  expectStagedOrder(sim.entries(), {{"world"}, {"geometry", "vision", "audio"}, {"visual_labels", "acoustic_labels"}, {"fusion"}}, 3);
}

TEST(ArbiterCore, RecoversALostDoneWithoutRunningTwice) {
  Simulation sim(readPnmlFile(kNets + "experts_only.pnml"), testConfig(3));
  sim.expert("audio").lose_done = [](const beft::done_t& d, int send) { return d.tick == 2 && send == 0; };
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  EXPECT_EQ(sim.donesLost(), 1);
  EXPECT_GE(sim.core().stats().fire_resends, 1);
  EXPECT_EQ(sim.runs("audio", 2), 1);  // the re-sent FIRE got the DONE again, not a second run
  EXPECT_EQ(countOf(sim.entries(), 'D', "audio", 2), 1);
}

TEST(ArbiterCore, DropsDuplicateAndStrayDones) {
  Simulation sim(readPnmlFile(kNets + "experts_only.pnml"), testConfig(2));
  sim.expert("geometry").done_copies = [](const beft::fire_t& f) { return f.tick == 0 ? 3 : 1; };
  sim.at(0.0003, [&sim] {  // while the world's first firing (id 1) runs
    beft::done_t stray{};
    stray.expert = "vision";
    stray.firing_id = 999;  // never issued
    sim.inject(stray);
    stray.expert = "nobody";
    stray.firing_id = 1;  // world's firing, from the wrong sender
    sim.inject(stray);
  });
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  EXPECT_EQ(sim.core().stats().duplicate_dones, 2);
  EXPECT_EQ(sim.core().stats().unknown_dones, 2);
  EXPECT_EQ(countOf(sim.entries(), 'D', "geometry", 0), 1);
  for (const auto& m : sim.markings())
    for (int32_t tokens : m.tokens) EXPECT_LE(tokens, 1);  // the copies produced no tokens
}

TEST(ArbiterCore, RetryStartsANewFiringForTheSameTick) {
  Simulation sim(chainNet({{"world", ""},
                           {"vision", "<timeout>2</timeout><on_timeout>retry</on_timeout><retries>2</retries>"}}),
                 testConfig(3));
  // Vision loses its first firing of tick 1: no DONE comes, the heartbeat goes on.
  sim.expert("vision").duration = [](const beft::fire_t& f) { return f.tick == 1 && f.firing_id == 4 ? -1.0 : 0.001; };
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  EXPECT_EQ(sim.core().stats().retries, 1);
  EXPECT_EQ(countOf(sim.entries(), 'R', "vision", 1), 1);
  EXPECT_EQ(countOf(sim.entries(), 'F', "vision", 1), 2);  // two firing ids for tick 1
  EXPECT_EQ(countOf(sim.entries(), 'D', "vision", 1), 1);
  EXPECT_EQ(sim.runs("vision", 1), 1);
  // The record of the first attempt, and the second.
  std::vector<FiringRecord> vision;
  for (const auto& r : sim.records())
    if (r.expert == "vision" && r.tick == 1) vision.push_back(r);
  ASSERT_EQ(vision.size(), 2u);
  EXPECT_EQ(vision[0].firing_id, 4);
  EXPECT_EQ(vision[0].outcome, "timeout");
  EXPECT_EQ(vision[0].action, "retry");
  EXPECT_NEAR(vision[0].duration_s, 2.0, 0.05);
  EXPECT_EQ(vision[1].attempt, 2);
  EXPECT_GT(vision[1].firing_id, vision[0].firing_id);
  EXPECT_EQ(vision[1].outcome, "ok");
}

TEST(ArbiterCore, RetriesSpentThenFailStopsTheRun) {
  Simulation sim(chainNet({{"world", ""},
                           {"vision", "<timeout>1</timeout><on_timeout>retry</on_timeout><retries>1</retries>"},
                           {"fusion", ""}}),
                 testConfig(5));
  sim.expert("vision").duration = [](const beft::fire_t& f) { return f.tick == 2 ? -1.0 : 0.001; };
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Failed);
  const std::string& why = sim.core().message();
  EXPECT_TRUE(contains(why, "vision (tick 2")) << why;
  EXPECT_TRUE(contains(why, "no DONE within 1 s")) << why;
  EXPECT_TRUE(contains(why, "after 1 retries")) << why;
  EXPECT_TRUE(contains(why, "t_vision is to fail the run")) << why;
  EXPECT_EQ(positionOf(sim.entries(), 'F', "fusion", 2), -1);
  // The final status says FAILED, several times.
  int failed = 0;
  for (const auto& s : sim.statuses())
    if (s.state == beft::run_status_t::STATE_FAILED) {
      ++failed;
      EXPECT_EQ(s.message, why);
      EXPECT_EQ(s.tick, 2);
    }
  EXPECT_EQ(failed, ArbiterConfig{}.final_status_repeats);
}

TEST(ArbiterCore, SkipGoesOnAndDropsTheLateDone) {
  Simulation sim(chainNet({{"world", ""}, {"dw", "<timeout>1</timeout><on_timeout>skip</on_timeout>"}, {"tasks", ""}}),
                 testConfig(4));
  // dw needs 1.5 s in tick 1: skipped at 1 s; it takes its tick-2 firing once free.
  sim.expert("dw").duration = [](const beft::fire_t& f) { return f.tick == 1 ? 1.5 : 0.001; };
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  EXPECT_EQ(sim.core().stats().skips, 1);
  EXPECT_EQ(countOf(sim.entries(), 'S', "dw", 1), 1);
  // Tasks ran in tick 1 although dw had not answered, right after the skip.
  const int skip = positionOf(sim.entries(), 'S', "dw", 1);
  EXPECT_EQ(positionOf(sim.entries(), 'F', "tasks", 1), skip + 1);
  // dw answered tick 1 after 1.5 s: too late, logged and dropped.
  EXPECT_EQ(sim.core().stats().late_dones, 1);
  EXPECT_EQ(countOf(sim.entries(), 'D', "dw", 2), 1);  // and it went on with tick 2
}

TEST(ArbiterCore, FailureOutcomeAppliesOnFailure) {
  Simulation sim(chainNet({{"world", ""},
                           {"audio", "<on_failure>retry</on_failure><retries>1</retries><after_retries>skip</after_retries>"},
                           {"fusion", ""}}),
                 testConfig(3));
  sim.expert("audio").fails = [](const beft::fire_t& f) { return f.tick == 1; };
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  std::vector<FiringRecord> audio;
  for (const auto& r : sim.records())
    if (r.expert == "audio" && r.tick == 1) audio.push_back(r);
  ASSERT_EQ(audio.size(), 2u);
  EXPECT_EQ(audio[0].outcome, "failed");
  EXPECT_EQ(audio[0].action, "retry");
  EXPECT_EQ(audio[0].message, "failed: scripted failure");
  EXPECT_EQ(audio[1].outcome, "failed");
  EXPECT_EQ(audio[1].action, "skip");
  EXPECT_EQ(sim.runs("audio", 1), 2);  // the retry is a new firing: the expert ran again
  EXPECT_EQ(countOf(sim.entries(), 'D', "fusion", 1), 1);
}

TEST(ArbiterCore, ADeadExpertIsFoundByItsHeartbeat) {
  // Firing timeout 30 s, heartbeat timeout 1 s: death is seen long before the timeout.
  Simulation sim(chainNet({{"world", ""},
                           {"vision", "<timeout>30</timeout><on_timeout>retry</on_timeout><retries>1</retries>"}}),
                 testConfig(0));
  const double death = 0.7;
  sim.expert("vision").dies_at = death;
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Failed);
  EXPECT_TRUE(contains(sim.core().message(), "vision")) << sim.core().message();
  EXPECT_TRUE(contains(sim.core().message(), "no heartbeat")) << sim.core().message();
  // Last heartbeat at 0.5 s: found dead at 1.5 s, its retry given up 1 s later;
  // the simulation ends after the final status was repeated.
  const double repeats = ArbiterConfig{}.final_status_repeats - 1;
  EXPECT_NEAR(sim.now(), 0.5 + 1.0 + 1.0 + repeats * ArbiterConfig{}.final_status_period_s, 0.01);
  std::vector<FiringRecord> vision;
  for (const auto& r : sim.records())
    if (r.expert == "vision" && r.outcome == "no-heartbeat") vision.push_back(r);
  ASSERT_EQ(vision.size(), 2u);
  EXPECT_EQ(vision[0].action, "retry");
  EXPECT_EQ(vision[1].action, "fail");
  EXPECT_LT(vision[0].start_s + vision[0].duration_s, death + 1.0);
}

TEST(ArbiterCore, AnExpertAliveAndWaitingForItsInputsIsNotTimedOut) {
  // Vision waits 4 s for inputs lost on the way (timeout 1 s), saying so in
  // its heartbeats: the firing goes on and ends with its DONE, not a retry.
  Simulation sim(chainNet({{"world", ""},
                           {"vision", "<timeout>1</timeout><on_timeout>retry</on_timeout><retries>1</retries>"}}),
                 testConfig(3));
  sim.expert("vision").duration = [](const beft::fire_t& f) { return f.tick == 1 ? 4.0 : 0.001; };
  sim.expert("vision").waits_for_inputs = true;
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  EXPECT_EQ(sim.core().stats().retries, 0);
  EXPECT_EQ(sim.runs("vision", 1), 1);

  // The same wait without saying so is a hung expert: timed out and retried.
  Simulation silent(chainNet({{"world", ""},
                              {"vision", "<timeout>1</timeout><on_timeout>retry</on_timeout><retries>1</retries>"}}),
                    testConfig(3));
  silent.expert("vision").duration = [](const beft::fire_t& f) { return f.tick == 1 && f.firing_id == 4 ? 4.0 : 0.001; };
  silent.run();
  EXPECT_EQ(silent.core().stats().retries, 1);
}

TEST(ArbiterCore, AnExpertThatWaitsAndDiesIsFoundByItsHeartbeat) {
  Simulation sim(chainNet({{"world", ""},
                           {"vision", "<timeout>1</timeout><on_timeout>fail</on_timeout>"}}),
                 testConfig(3));
  sim.expert("vision").duration = [](const beft::fire_t& f) { return f.tick == 1 ? 60.0 : 0.001; };
  sim.expert("vision").waits_for_inputs = true;
  sim.expert("vision").dies_at = 5.0;
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Failed);
  EXPECT_TRUE(contains(sim.core().message(), "no heartbeat")) << sim.core().message();
}

TEST(ArbiterCore, ReportsADeadlockAtOnce) {
  // After the world step, t_join needs two tokens where the world puts one.
  const Net net = readPnmlString(
      "<pnml><net id=\"n\">"
      "<place id=\"p0\"><initialMarking><text>1</text></initialMarking></place><place id=\"p1\"/><place id=\"p2\"/>"
      "<transition id=\"t_world\"><toolspecific tool=\"beft\"><expert>world</expert></toolspecific></transition>"
      "<transition id=\"t_join\"><toolspecific tool=\"beft\"><silent/></toolspecific></transition>"
      "<transition id=\"t_tick\"><toolspecific tool=\"beft\"><tick/></toolspecific></transition>"
      "<arc id=\"a1\" source=\"p0\" target=\"t_world\"/><arc id=\"a2\" source=\"t_world\" target=\"p1\"/>"
      "<arc id=\"a3\" source=\"p1\" target=\"t_join\"><inscription><text>2</text></inscription></arc>"
      "<arc id=\"a4\" source=\"t_join\" target=\"p2\"/><arc id=\"a5\" source=\"p2\" target=\"t_tick\"/>"
      "<arc id=\"a6\" source=\"t_tick\" target=\"p0\"/></net></pnml>",
      "deadlock.pnml");
  Simulation sim(net, testConfig(0));
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Failed);
  EXPECT_EQ(sim.core().message(),
            "deadlock in tick 0: no transition is enabled and no expert is running; marking: p1=1");
  const int done = positionOf(sim.entries(), 'D', "world", 0);
  ASSERT_GE(done, 0);
  EXPECT_EQ(sim.statuses().back().state, beft::run_status_t::STATE_FAILED);
  // Failed in the same step as the world's DONE: no time passed.
  const auto failed = std::find_if(sim.statuses().begin(), sim.statuses().end(), [](const beft::run_status_t& s) {
    return s.state == beft::run_status_t::STATE_FAILED;
  });
  ASSERT_NE(failed, sim.statuses().end());
  EXPECT_EQ(sim.markings().back().event, "done world");
}

TEST(ArbiterCore, WaitsForEveryExpertBeforeTheFirstFire) {
  Simulation sim(readPnmlFile(kNets + "experts_only.pnml"), testConfig(1));
  sim.expert("audio").starts_at = 7.0;
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  ASSERT_FALSE(sim.entries().empty());
  EXPECT_GE(sim.entries().front().time, 7.0);  // no FIRE before the last expert was heard
  // WAITING at start and every report period, naming only audio once the others are up.
  std::vector<std::string> waiting;
  for (const auto& s : sim.statuses())
    if (s.state == beft::run_status_t::STATE_WAITING) waiting.push_back(s.message);
  ASSERT_EQ(waiting.size(), 3u);  // at 0, 3 and 6 s
  EXPECT_EQ(waiting[1], "waiting for heartbeats from: audio");
  EXPECT_EQ(waiting[2], "waiting for heartbeats from: audio");
}

TEST(ArbiterCore, WaitsForAServiceItIsToldToWaitFor) {
  ArbiterConfig config = testConfig(1);
  config.also_wait_for = {"planner"};
  Simulation sim(readPnmlFile(kNets + "experts_only.pnml"), config);
  sim.service("planner", 4.0);
  sim.service("viewer", kNever);  // not waited for: never heard, never missed
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  ASSERT_FALSE(sim.entries().empty());
  EXPECT_GE(sim.entries().front().time, 4.0);  // no FIRE before the planner was heard
  std::vector<std::string> waiting;
  for (const auto& s : sim.statuses())
    if (s.state == beft::run_status_t::STATE_WAITING) waiting.push_back(s.message);
  ASSERT_EQ(waiting.size(), 2u);  // at 0 and 3 s
  EXPECT_EQ(waiting[1], "waiting for heartbeats from: planner");
}

TEST(ArbiterCore, FailsWhenAServiceItWaitsForNeverStarts) {
  ArbiterConfig config = testConfig(1);
  config.startup_timeout_s = 2.0;
  config.also_wait_for = {"planner"};
  Simulation sim(readPnmlFile(kNets + "experts_only.pnml"), config);
  sim.service("planner", kNever);
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Failed);
  EXPECT_TRUE(contains(sim.core().message(), "no heartbeat within 2 s from: planner")) << sim.core().message();
  EXPECT_TRUE(sim.fires().empty());
}

TEST(ArbiterCore, FailsWhenAnExpertNeverStarts) {
  ArbiterConfig config = testConfig(1);
  config.startup_timeout_s = 2.0;
  Simulation sim(readPnmlFile(kNets + "experts_only.pnml"), config);
  sim.expert("audio").starts_at = kNever;
  sim.expert("fusion").starts_at = kNever;
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Failed);
  EXPECT_TRUE(contains(sim.core().message(), "no heartbeat within 2 s from: audio, fusion")) << sim.core().message();
  EXPECT_TRUE(sim.fires().empty());
}

TEST(ArbiterCore, StopRequestEndsTheRunAtTheEndOfTheTick) {
  Simulation sim(readPnmlFile(kNets + "default.pnml"), testConfig(0));
  // Durations of 10 ms: tick 2 runs from 0.14 s to 0.21 s; stop in the middle of it.
  for (const auto& stage : kDefaultStages)
    for (const auto& name : stage) sim.expert(name).duration = [](const beft::fire_t&) { return 0.01; };
  sim.at(0.17, [&sim] { sim.core().onStopRequest("operator pressed stop"); });
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  EXPECT_EQ(sim.core().message(), "stopped on request after 3 ticks: operator pressed stop");
  expectStagedOrder(sim.entries(), kDefaultStages, 3);  // tick 2 completed
  EXPECT_EQ(positionOf(sim.entries(), 'F', "world", 3), -1);
}

TEST(ArbiterCore, StopRequestDoesNotWaitOnABrokenTick) {
  Simulation sim(chainNet({{"world", ""},
                           {"vision", "<timeout>1</timeout><on_timeout>retry</on_timeout><retries>3</retries>"}}),
                 testConfig(0));
  sim.expert("vision").duration = [](const beft::fire_t& f) { return f.tick == 1 ? -1.0 : 0.001; };
  sim.at(0.5, [&sim] { sim.core().onStopRequest("shutting down"); });
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  EXPECT_TRUE(contains(sim.core().message(), "stopped on request in tick 1 (shutting down), which could not complete"))
      << sim.core().message();
  EXPECT_EQ(sim.core().stats().retries, 0);  // no retry once a stop is requested
  EXPECT_EQ(sim.records().back().action, "stop");
}

TEST(ArbiterCore, FiringIdsContinueAboveWhatExpertsReport) {
  Simulation sim(chainNet({{"world", ""}, {"vision", ""}}), testConfig(1));
  sim.expert("vision").reported_firing_id = 41;  // ran firings of an earlier arbiter
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Finished) << sim.core().message();
  ASSERT_FALSE(sim.fires().empty());
  EXPECT_EQ(sim.fires().front().firing_id, 42);
}

TEST(ArbiterCore, RefusesToSpinOnASilentCycle) {
  const Net net = readPnmlString(
      "<pnml><net id=\"n\">"
      "<place id=\"p0\"><initialMarking><text>1</text></initialMarking></place><place id=\"p1\"/>"
      "<place id=\"q\"><initialMarking><text>1</text></initialMarking></place>"
      "<transition id=\"t_world\"><toolspecific tool=\"beft\"><expert>world</expert></toolspecific></transition>"
      "<transition id=\"t_spin\"><toolspecific tool=\"beft\"><silent/></toolspecific></transition>"
      "<transition id=\"t_tick\"><toolspecific tool=\"beft\"><tick/></toolspecific></transition>"
      "<arc id=\"a1\" source=\"p0\" target=\"t_world\"/><arc id=\"a2\" source=\"t_world\" target=\"p1\"/>"
      "<arc id=\"a3\" source=\"p1\" target=\"t_tick\"/><arc id=\"a4\" source=\"t_tick\" target=\"p0\"/>"
      "<arc id=\"a5\" source=\"q\" target=\"t_spin\"/><arc id=\"a6\" source=\"t_spin\" target=\"q\"/>"
      "</net></pnml>",
      "spin.pnml");
  ArbiterConfig config = testConfig(1);
  config.max_silent_firings_per_step = 1000;
  Simulation sim(net, config);
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Failed);
  EXPECT_TRUE(contains(sim.core().message(), "cycle without an expert")) << sim.core().message();
}

TEST(ArbiterCore, AbortEndsTheRunAtOnce) {
  Simulation sim(readPnmlFile(kNets + "experts_only.pnml"), testConfig(0));
  sim.expert("vision").duration = [](const beft::fire_t&) { return 5.0; };
  sim.at(1.0, [&sim] { sim.core().onAbort("interrupted twice"); });
  sim.run();
  ASSERT_EQ(sim.core().state(), RunState::Failed);
  EXPECT_EQ(sim.core().message(), "aborted: interrupted twice");
  // Vision's firing in flight is recorded as abandoned.
  const auto abandoned = std::find_if(sim.records().begin(), sim.records().end(),
                                      [](const FiringRecord& r) { return r.outcome == "abandoned"; });
  ASSERT_NE(abandoned, sim.records().end());
  EXPECT_EQ(abandoned->expert, "vision");
}

}  // namespace
}  // namespace beft::arbiter

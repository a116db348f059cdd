// The arbiter's logic, free of LCM: it owns the marking, decides which
// transitions fire, tracks the firings in flight and applies the net's
// policies. It is fed events (DONE, HEARTBEAT, stop request, time passing)
// by one thread and talks to the world only through ArbiterOutput, so tests
// drive it with a scripted clock and mock experts.
//
// Run lifecycle:
//   WAITING  until every expert of the net has sent a heartbeat (bounded by
//            the startup timeout);
//   RUNNING  ticks: every step starts every enabled transition whose expert
//            is idle (experts run one firing at a time), fires silent
//            transitions at once, and fires the tick transition when nothing
//            else can start, unless the run is held there (RUN_CONTROL:
//            paused, or stepped to that tick) or the real-time pace says the
//            next tick's time has not come: only the start of a tick waits,
//            so a held or paced run computes what a fast one does;
//   FINISHED when the tick transition is enabled after the last tick
//            (--max-ticks) or after a stop request, and nothing is running;
//   FAILED   on a deadlock, a "fail" policy, a startup timeout or an abort.
// The final status is sent several times so it survives UDP loss.
#pragma once

#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/frontier_t.hpp>
#include <beft/heartbeat_t.hpp>
#include <beft/marking_t.hpp>
#include <beft/run_control_t.hpp>
#include <beft/run_status_t.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "lib/petri/petri_net.hpp"
#include "services/arbiter/run_control.hpp"
#include "services/arbiter/tick_pace.hpp"

namespace beft::arbiter {

// Monotonic wall time in seconds; tests script it.
class Clock {
 public:
  virtual ~Clock() = default;
  virtual double now() const = 0;
};

// One attempt of one firing, as it ended.
struct FiringRecord {
  int64_t tick = 0;
  int64_t firing_id = 0;
  std::string expert;
  std::string transition;
  int attempt = 1;                 // 1 for the first firing, 2 for the first retry, ...
  double start_s = 0.0;            // first FIRE, wall seconds since the run started
  double duration_s = 0.0;         // first FIRE to DONE (or to expiry), wall
  double expert_duration_s = -1.0; // the expert's own figure from DONE; -1 without DONE
  std::string outcome;             // ok | failed | timeout | no-heartbeat | abandoned
  std::string action;              // "" when done, else retry | skip | fail | stop
  std::string message;             // the expert's failure message or the expiry reason
};

// Where the core's decisions go: live, LCM and the run's log; in tests, a recorder.
// A FRONTIER message as sent: the arbiter's sender id and its number.
struct FrontierMark {
  int64_t sender = 0;
  int64_t sequence = 0;  // 0: none sent
};

class ArbiterOutput {
 public:
  virtual ~ArbiterOutput() = default;
  virtual void sendFire(const beft::fire_t& fire) = 0;
  // Publishes what the experts fired so far had published (the FIREs that
  // follow come after it); returns its mark, {0, 0} where nothing tracks it.
  virtual FrontierMark sendFrontier(const beft::frontier_t& frontier) {
    (void)frontier;
    return {};
  }
  virtual void sendMarking(const beft::marking_t& marking) = 0;
  virtual void sendRunStatus(const beft::run_status_t& status) = 0;
  // RUN_CONTROL_STATE: how the run goes on, and the request last applied.
  virtual void sendRunControlState(const beft::run_control_t& state) { (void)state; }
  virtual void firingEnded(const FiringRecord& record) = 0;
};

struct ArbiterConfig {
  int64_t max_ticks = 0;              // 0: until a stop request
  double dt_s = 0.1;                  // simulated time per tick, for utime = tick * dt
  double startup_timeout_s = 30.0;    // wait for the first heartbeat of every expert
  // Processes outside the net whose first heartbeat the run also waits for:
  // services the experts ask within a tick (the planner). A request sent
  // before such a service is up is lost, and the answer waited for then
  // depends on how fast the machine started it, not on the seed.
  std::vector<std::string> also_wait_for;
  double startup_report_period_s = 3.0;  // how often to say whom it still waits for
  // FIRE is re-sent this often until DONE: a lost FIRE (the one control
  // message not repaired by the transport: each expert takes only its own
  // from the channel) costs this much.
  double resend_period_s = 0.005;
  double heartbeat_timeout_s = 3.0;   // default for transitions that give none
  int final_status_repeats = 5;       // the final RUN_STATUS, sent this many times
  double final_status_period_s = 0.05;
  int64_t max_silent_firings_per_step = 100000;  // guard against a silent cycle
  Pace pace = Pace::kFast;              // real-time: a tick starts no sooner than its simulated time
  double control_state_period_s = 0.2;  // RUN_CONTROL_STATE repeated this often (and sent on a change)
};

enum class RunState { Waiting, Running, Finished, Failed };
const char* runStateName(RunState state);

struct ArbiterStats {
  int64_t firings_started = 0;   // FIREs with a new id (first attempts and retries)
  int64_t firings_done = 0;      // DONE accepted with OUTCOME_OK
  int64_t fire_resends = 0;
  int64_t duplicate_dones = 0;   // DONE again for a firing already completed
  int64_t late_dones = 0;        // DONE for a firing abandoned (expired, retried)
  int64_t unknown_dones = 0;     // DONE for an id never issued, or from the wrong expert
  int64_t retries = 0;
  int64_t skips = 0;
  int64_t steps = 0;             // MARKING messages published
  int64_t ticks_completed = 0;  // ticks whose end was reached
};

// Where a restarted arbiter takes the run up again (crash-only): what it had
// published before it died, read from the run's log.
struct ResumePoint {
  beft::marking_t marking{};  // the last MARKING it published (sent before its step's FIREs)
  std::map<std::string, beft::fire_t> newest_fire;  // per expert, the newest FIRE logged
  std::set<int64_t> done_firing_ids;                // firings whose DONE the log holds
  int64_t highest_firing_id = 0;                    // of every FIRE logged
  std::optional<beft::run_control_t> control;       // the last RUN_CONTROL_STATE: a held run holds again
};

class ArbiterCore {
 public:
  ArbiterCore(Net net, ArbiterConfig config, Clock& clock, ArbiterOutput& output);

  // Starts waiting for the experts' heartbeats (RUN_STATUS WAITING).
  void start();
  // Instead of start(), after a crash: the marking, tick and step of the
  // last MARKING taken up again with its firings in flight, their FIREs
  // re-sent (an expert that already ran one answers with its DONE again). A
  // firing in flight is the expert's newest FIRE when the log holds no DONE
  // for it; else its FIRE was never sent (the MARKING goes out first) and it
  // gets a new id.
  // Throws std::invalid_argument if the point does not fit this net.
  void resume(const ResumePoint& point);
  void onDone(const beft::done_t& done);
  void onHeartbeat(const beft::heartbeat_t& heartbeat);
  // End the run at the end of the current tick (FINISHED).
  void onStopRequest(const std::string& why);
  // End the run now (FAILED), e.g. a second Ctrl-C.
  void onAbort(const std::string& why);
  // A request on RUN_CONTROL: run on, pause after the current tick, or hold
  // after a given tick (run_control.hpp); answered on RUN_CONTROL_STATE.
  void onRunControl(const beft::run_control_t& request);
  // Re-sends, timeouts, heartbeats, startup reports: call when nextDeadline() passes.
  void onTimeAdvanced();

  // Wall time of the next thing onTimeAdvanced() must do (+inf if nothing).
  double nextDeadline() const;

  RunState state() const { return state_; }
  bool ended() const { return state_ == RunState::Finished || state_ == RunState::Failed; }
  // Ended and the final status sent the configured number of times.
  bool done() const { return ended() && final_sends_left_ == 0; }
  const std::string& message() const { return message_; }
  int64_t tick() const { return tick_; }
  // Held between ticks: tick() has finished and the next waits for a request.
  bool held() const { return held_; }
  // What RUN_CONTROL_STATE says now (utime 0).
  beft::run_control_t controlState() const { return control_.state(tick_, held_); }
  const Marking& marking() const { return marking_; }
  const Net& net() const { return net_; }
  const ArbiterStats& stats() const { return stats_; }
  // Firings sent and not yet ended (DONE, expiry).
  int firingsInFlight() const;
  // Experts, and processes of also_wait_for, whose first heartbeat has not arrived yet.
  std::vector<std::string> missingProcesses() const;

 private:
  struct Running {
    int transition = -1;
    int64_t firing_id = 0;
    int64_t tick = 0;
    int attempt = 1;
    double attempt_start = 0.0;  // this attempt's first FIRE
    double last_send = 0.0;
    double last_waiting = 0.0;   // last heartbeat saying it waits for its inputs
    FrontierMark after;          // the FRONTIER message this firing comes after
  };
  struct ExpertState {
    std::string name;
    bool heard = false;
    double last_heartbeat = 0.0;
    bool reported_silent = false;  // idle and without heartbeat: warned once
    bool warned_foreign = false;   // reported a firing id this arbiter never issued
    std::optional<Running> running;
  };
  struct Deadlines {  // of the firing in flight of one expert, wall seconds
    double resend = 0.0;
    double timeout = 0.0;
    double heartbeat = 0.0;
  };
  struct EndedFiring {
    int expert = -1;
    bool completed = false;  // DONE accepted (else abandoned: expired or retried)
    int duplicates = 0;      // DONEs received again after it completed
  };

  void beginRun();
  void step(const std::string& event);
  // Whether the tick transition may fire now, opening tick_ + 1: not while
  // the run is held after tick_, nor before the pace allows.
  bool nextTickMayStart();
  void noteHeld();
  void sendControlState();
  double firingDeadline() const;
  // send_now false: the FIRE goes out after the step's MARKING.
  void startFiring(int transition, int attempt, int64_t tick, bool send_now = true);
  void sendFire(int expert);
  void completeFiring(int expert, const beft::done_t& done);
  // A firing did not succeed (outcome: failed | timeout | no-heartbeat): apply the policy.
  void applyPolicy(int expert, ExpiryAction action, const std::string& outcome,
                   const std::string& reason, double expert_duration_s);
  void endFiring(int expert, bool completed);
  FiringRecord recordOf(int expert, const std::string& outcome, const std::string& action,
                        const std::string& message, double expert_duration_s) const;
  void fail(const std::string& why);
  void finish(const std::string& why);
  void endRun(RunState state, const std::string& why);
  void checkRunningFirings(double now);
  Deadlines deadlinesOf(int expert) const;
  void sendStatus(int8_t state, const std::string& message);
  void publishMarking(const std::string& event);
  bool anyRunning() const;
  bool endingAtTickEnd() const;
  double heartbeatTimeout(const Transition& transition) const;
  int expertIndex(const std::string& name) const;
  int64_t utimeOfTick(int64_t tick) const;
  std::string describeFiring(const Running& running, int expert) const;

  Net net_;
  ArbiterConfig config_;
  Clock& clock_;
  ArbiterOutput& output_;

  RunState state_ = RunState::Waiting;
  std::string message_;
  Marking marking_;
  std::vector<ExpertState> experts_;
  std::map<std::string, bool> services_heard_;  // also_wait_for: first heartbeat arrived
  std::vector<int> transition_expert_;  // expert index per transition, -1 if silent
  int64_t tick_ = 0;
  int64_t next_firing_id_ = 1;
  std::vector<int> unsent_fires_;  // experts started in this step, FIRE not sent yet
  // What the experts' DONEs said they had published since the last FRONTIER
  // message ((sender, channel) -> last sequence number), and that message.
  std::map<std::pair<int64_t, std::string>, int64_t> frontier_changes_;
  FrontierMark frontier_;
  void notePublished(const beft::done_t& done);
  void sendFrontierChanges();
  int64_t highest_reported_firing_id_ = 0;
  double run_start_ = 0.0;
  double startup_deadline_ = 0.0;
  double next_startup_report_ = 0.0;
  bool started_ = false;
  bool stop_requested_ = false;
  std::string stop_reason_;
  bool in_step_ = false;
  int final_sends_left_ = 0;
  double next_final_send_ = 0.0;
  std::map<int64_t, EndedFiring> recently_ended_;  // bounded window of ended ids
  std::vector<std::string> pending_events_;        // for the next MARKING's event text
  RunControl control_;
  TickPace pace_;
  bool held_ = false;                   // the tick transition waits for a request
  std::optional<double> pace_wait_;     // the tick transition waits for the pace until then
  double next_control_state_ = 0.0;     // the next periodic RUN_CONTROL_STATE
  std::pair<std::string, int64_t> last_refused_{"", -1};  // said once, not at every resend
  ArbiterStats stats_;
};

}  // namespace beft::arbiter

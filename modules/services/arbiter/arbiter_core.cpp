#include "services/arbiter/arbiter_core.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "lib/transport/control_messages.hpp"
#include "lib/common/log.hpp"

namespace beft::arbiter {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
constexpr size_t kEndedWindow = 4096;  // ended firing ids remembered, to classify stray DONEs

std::string seconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.3g s", s);
  return buffer;
}

std::string joinNames(const std::vector<std::string>& names, const char* separator = ", ") {
  std::string text;
  for (const auto& name : names) {
    if (!text.empty()) text += separator;
    text += name;
  }
  return text;
}

}  // namespace

const char* runStateName(RunState state) {
  switch (state) {
    case RunState::Waiting: return "WAITING";
    case RunState::Running: return "RUNNING";
    case RunState::Finished: return "FINISHED";
    case RunState::Failed: return "FAILED";
  }
  return "?";
}

ArbiterCore::ArbiterCore(Net net, ArbiterConfig config, Clock& clock, ArbiterOutput& output)
    : net_(std::move(net)), config_(config), clock_(clock), output_(output), pace_(config.pace, config.dt_s) {
  marking_ = net_.initialMarking();
  for (const auto& name : net_.experts()) {
    ExpertState expert;
    expert.name = name;
    experts_.push_back(expert);
  }
  for (const auto& transition : net_.transitions)
    transition_expert_.push_back(transition.silent() ? -1 : expertIndex(transition.expert));
  for (const auto& name : config_.also_wait_for)
    if (expertIndex(name) < 0) services_heard_[name] = false;
}

int ArbiterCore::firingsInFlight() const {
  int count = 0;
  for (const auto& expert : experts_) count += expert.running ? 1 : 0;
  return count;
}

std::vector<std::string> ArbiterCore::missingProcesses() const {
  std::vector<std::string> missing;
  for (const auto& expert : experts_)
    if (!expert.heard) missing.push_back(expert.name);
  for (const auto& [name, heard] : services_heard_)
    if (!heard) missing.push_back(name);
  return missing;
}

void ArbiterCore::start() {
  if (started_) return;
  started_ = true;
  const double now = clock_.now();
  run_start_ = now;
  startup_deadline_ = now + config_.startup_timeout_s;
  next_startup_report_ = now + config_.startup_report_period_s;
  sendControlState();
  const auto missing = missingProcesses();
  if (missing.empty()) {
    beginRun();
    return;
  }
  log::info("waiting up to ", seconds(config_.startup_timeout_s), " for the first heartbeat of: ",
            joinNames(missing));
  sendStatus(beft::run_status_t::STATE_WAITING, "waiting for heartbeats from: " + joinNames(missing));
}

void ArbiterCore::resume(const ResumePoint& point) {
  const beft::marking_t& last = point.marking;
  if (last.place_ids.size() != net_.places.size())
    throw std::invalid_argument("the log's MARKING has " + std::to_string(last.place_ids.size()) +
                                " places, the net " + std::to_string(net_.places.size()));
  for (std::size_t p = 0; p < net_.places.size(); ++p) {
    if (last.place_ids[p] != net_.places[p].id)
      throw std::invalid_argument("the log's MARKING names place " + last.place_ids[p] + " where the net has " +
                                  net_.places[p].id);
    marking_[p] = last.tokens[p];
  }
  started_ = true;
  const double now = clock_.now();
  run_start_ = now;
  tick_ = last.tick;
  pace_.restart(now, tick_);
  if (point.control) control_.restore(*point.control);
  sendControlState();
  stats_.steps = last.step;
  next_firing_id_ = std::max<int64_t>(next_firing_id_, point.highest_firing_id + 1);
  for (auto& expert : experts_) {
    expert.heard = true;
    expert.last_heartbeat = now;
  }
  for (auto& service : services_heard_) service.second = true;
  for (const std::string& name : last.running) {
    const int e = expertIndex(name);
    if (e < 0) throw std::invalid_argument("the log's MARKING runs " + name + ", not an expert of this net");
    const auto fire = point.newest_fire.find(name);
    const bool fire_sent = fire != point.newest_fire.end() && !point.done_firing_ids.count(fire->second.firing_id);
    // The transition: the sent FIRE's, else the expert's (its newest FIRE's if it has several).
    int transition = -1;
    for (std::size_t t = 0; t < net_.transitions.size(); ++t) {
      if (transition_expert_[t] != e) continue;
      if (transition < 0 || (fire != point.newest_fire.end() && net_.transitions[t].id == fire->second.transition))
        transition = static_cast<int>(t);
    }
    if (transition < 0) throw std::invalid_argument("no transition of this net fires " + name);
    Running running;
    running.transition = transition;
    running.firing_id = fire_sent ? fire->second.firing_id : next_firing_id_++;
    running.tick = fire_sent ? fire->second.tick : last.tick;
    running.attempt_start = now;
    experts_[e].running = running;
  }
  state_ = RunState::Running;
  log::info("resumed at tick ", tick_, ", step ", stats_.steps, ", ", firingsInFlight(),
            " firing(s) in flight; next firing id ", next_firing_id_);
  for (std::size_t e = 0; e < experts_.size(); ++e)
    if (experts_[e].running) sendFire(static_cast<int>(e));
  step("resumed");
}

void ArbiterCore::beginRun() {
  state_ = RunState::Running;
  run_start_ = clock_.now();
  pace_.restart(run_start_, 0);
  // Experts drop a FIRE whose id is not above the last they ran: continue
  // above anything they report, so a restarted arbiter is heard.
  next_firing_id_ = std::max<int64_t>(1, highest_reported_firing_id_ + 1);
  log::info("every expert", services_heard_.empty() ? "" : " and service", " is up; the run starts (first firing id ",
            next_firing_id_, ")");
  sendStatus(beft::run_status_t::STATE_RUNNING, "tick 0");
  step("start");
}

void ArbiterCore::onHeartbeat(const beft::heartbeat_t& heartbeat) {
  const int e = expertIndex(heartbeat.process);
  if (e < 0) {
    // A service the run waits for, or another process (blackboard, viewer).
    const auto service = services_heard_.find(heartbeat.process);
    if (service == services_heard_.end() || service->second) return;
    service->second = true;
    if (state_ == RunState::Waiting && started_) {
      log::info("heard ", heartbeat.process, " (pid ", heartbeat.pid, " on ", heartbeat.host, ")");
      if (missingProcesses().empty()) beginRun();
    }
    return;
  }
  ExpertState& expert = experts_[e];
  const bool first = !expert.heard;
  expert.heard = true;
  expert.last_heartbeat = clock_.now();
  if (expert.reported_silent) {
    expert.reported_silent = false;
    log::info("expert ", expert.name, " sends heartbeats again");
  }
  // Alive and waiting for its inputs (lost on the way and being repaired) is
  // not hung: the firing's timeout counts from the last such heartbeat.
  if (expert.running && heartbeat.state == "waiting") expert.running->last_waiting = expert.last_heartbeat;
  if (state_ == RunState::Waiting) {
    highest_reported_firing_id_ = std::max(highest_reported_firing_id_, heartbeat.last_firing_id);
    if (first && started_) {
      log::info("heard ", expert.name, " (pid ", heartbeat.pid, " on ", heartbeat.host, ")");
      if (missingProcesses().empty()) beginRun();
    }
  } else if (state_ == RunState::Running && heartbeat.last_firing_id >= next_firing_id_ &&
             !expert.warned_foreign) {
    expert.warned_foreign = true;
    log::warn("expert ", expert.name, " reports firing ", heartbeat.last_firing_id,
              ", which this arbiter never issued: is another arbiter running on this LCM URL?");
  }
}

void ArbiterCore::onDone(const beft::done_t& done) {
  if (state_ != RunState::Running) {
    log::info("DONE from ", done.expert, " for firing ", done.firing_id, " while the run is ",
              runStateName(state_), ": dropped");
    return;
  }
  const int e = expertIndex(done.expert);
  if (e >= 0 && experts_[e].running && experts_[e].running->firing_id == done.firing_id) {
    notePublished(done);
    completeFiring(e, done);
    step("done " + done.expert);
    return;
  }
  // Not the firing in flight: say why it is dropped.
  if (const auto found = recently_ended_.find(done.firing_id); found != recently_ended_.end()) {
    EndedFiring& ended = found->second;
    if (ended.expert != e) {
      ++stats_.unknown_dones;
      log::warn("DONE from '", done.expert, "' for firing ", done.firing_id,
                ", which was addressed to ", experts_[ended.expert].name, ": dropped");
    } else if (ended.completed) {
      // Expected when a firing outlasts the re-send period: the expert answers
      // every copy of the FIRE. Said once per firing.
      ++stats_.duplicate_dones;
      if (++ended.duplicates == 1)
        log::info("duplicate DONE from ", done.expert, " for firing ", done.firing_id,
                  ": dropped (and any further copies)");
    } else {
      ++stats_.late_dones;
      log::warn("late DONE from ", done.expert, " for firing ", done.firing_id, " (tick ", done.tick,
                "), which was already given up: dropped");
    }
    return;
  }
  ++stats_.unknown_dones;
  if (done.firing_id >= next_firing_id_)
    log::warn("DONE from ", done.expert, " for firing ", done.firing_id,
              ", which this arbiter never issued (is another arbiter running on this LCM URL?): dropped");
  else if (e < 0)
    log::warn("DONE from '", done.expert, "', which is not an expert of this net: dropped");
  else
    log::warn("DONE from ", done.expert, " for old firing ", done.firing_id, ": dropped");
}

void ArbiterCore::onStopRequest(const std::string& why) {
  if (ended()) return;
  if (state_ == RunState::Waiting) {
    finish("stopped before the first tick: " + why);
    return;
  }
  if (stop_requested_) return;
  stop_requested_ = true;
  stop_reason_ = why;
  log::info("stop requested (", why, "): the run ends at the end of tick ", tick_);
  step("stop requested");
}

void ArbiterCore::onAbort(const std::string& why) {
  if (ended()) return;
  fail("aborted: " + why);
}

void ArbiterCore::onTimeAdvanced() {
  const double now = clock_.now();
  if (started_ && !ended() && now >= next_control_state_) sendControlState();
  if (ended()) {
    if (final_sends_left_ > 0 && now >= next_final_send_) {
      sendStatus(state_ == RunState::Finished ? beft::run_status_t::STATE_FINISHED
                                              : beft::run_status_t::STATE_FAILED,
                 message_);
      --final_sends_left_;
      next_final_send_ = now + config_.final_status_period_s;
    }
    return;
  }
  if (state_ == RunState::Waiting) {
    if (!started_) return;
    const auto missing = missingProcesses();
    if (now >= startup_deadline_) {
      fail("no heartbeat within " + seconds(config_.startup_timeout_s) + " from: " +
           joinNames(missing) + " (are they started, on the same --lcm-url?)");
    } else if (now >= next_startup_report_) {
      log::info("still waiting for heartbeats from: ", joinNames(missing), " (",
                seconds(startup_deadline_ - now), " left)");
      sendStatus(beft::run_status_t::STATE_WAITING, "waiting for heartbeats from: " + joinNames(missing));
      while (next_startup_report_ <= now) next_startup_report_ += config_.startup_report_period_s;
    }
    return;
  }
  checkRunningFirings(now);
  if (state_ == RunState::Running && pace_wait_ && now >= *pace_wait_) {
    pace_wait_.reset();
    step("real-time pace");
  }
}

void ArbiterCore::checkRunningFirings(double now) {
  bool changed = false;
  for (size_t e = 0; e < experts_.size() && state_ == RunState::Running; ++e) {
    ExpertState& expert = experts_[e];
    if (!expert.running) {
      if (expert.heard && !expert.reported_silent &&
          now >= expert.last_heartbeat + config_.heartbeat_timeout_s) {
        expert.reported_silent = true;
        log::warn("no heartbeat from ", expert.name, " for ", seconds(now - expert.last_heartbeat),
                  " (idle; its next firing will tell whether it is gone)");
      }
      continue;
    }
    const Running& running = *expert.running;
    const Transition& transition = net_.transitions[running.transition];
    const Deadlines due = deadlinesOf(static_cast<int>(e));
    if (now >= due.timeout) {
      applyPolicy(static_cast<int>(e), transition.policy.on_timeout, "timeout",
                  "no DONE within " + seconds(transition.policy.timeout_s), -1.0);
      changed = true;
    } else if (now >= due.heartbeat) {
      applyPolicy(static_cast<int>(e), transition.policy.on_timeout, "no-heartbeat",
                  "no heartbeat for " + seconds(now - (due.heartbeat - heartbeatTimeout(transition))) +
                      " (expert gone?)",
                  -1.0);
      changed = true;
    } else if (now >= due.resend) {
      sendFire(static_cast<int>(e));
      ++stats_.fire_resends;
    }
  }
  if (changed) step("expiry");
}

double ArbiterCore::nextDeadline() const {
  double next = firingDeadline();
  if (started_ && !ended()) next = std::min(next, next_control_state_);
  if (pace_wait_ && state_ == RunState::Running) next = std::min(next, *pace_wait_);
  return next;
}

double ArbiterCore::firingDeadline() const {
  double next = kNever;
  if (ended()) return final_sends_left_ > 0 ? next_final_send_ : kNever;
  if (state_ == RunState::Waiting)
    return started_ ? std::min(startup_deadline_, next_startup_report_) : kNever;
  for (const auto& expert : experts_) {
    if (!expert.running) {
      if (expert.heard && !expert.reported_silent)
        next = std::min(next, expert.last_heartbeat + config_.heartbeat_timeout_s);
      continue;
    }
    const Deadlines due = deadlinesOf(static_cast<int>(&expert - experts_.data()));
    next = std::min({next, due.resend, due.timeout, due.heartbeat});
  }
  return next;
}

// One formula for both nextDeadline() and the checks, so a deadline that is
// announced is also found due at that very time.
ArbiterCore::Deadlines ArbiterCore::deadlinesOf(int e) const {
  const ExpertState& expert = experts_[e];
  const Running& running = *expert.running;
  const Transition& transition = net_.transitions[running.transition];
  // A first attempt counts from the last heartbeat (an expert already gone
  // is found at once); a retry gives a restarted expert a full period.
  const double heartbeat_reference = running.attempt == 1
                                         ? expert.last_heartbeat
                                         : std::max(expert.last_heartbeat, running.attempt_start);
  Deadlines due;
  due.resend = running.last_send + config_.resend_period_s;
  // An expert that said it waits for its inputs is given up by its
  // heartbeat (dead), not by the timeout (hung), which counts from after
  // that heartbeat's own deadline.
  const double waiting_until = running.last_waiting > 0.0 ? running.last_waiting + heartbeatTimeout(transition) : 0.0;
  due.timeout = std::max(running.attempt_start, waiting_until) + transition.policy.timeout_s;
  due.heartbeat = heartbeat_reference + heartbeatTimeout(transition);
  return due;
}

void ArbiterCore::step(const std::string& event) {
  if (state_ != RunState::Running) return;
  std::string text = event;
  const auto note = [&text](const std::string& what) { text += (text.empty() ? "" : "; ") + what; };
  const int tick_transition = net_.tick_transition;
  const Transition& tick = net_.transitions[tick_transition];
  int64_t silent_firings = 0;
  bool tick_opened = false;
  bool tick_waits = false;  // held, or paced
  const bool was_held = held_;
  while (true) {
    // After the last tick, nothing new starts once the tick transition is enabled.
    if (endingAtTickEnd() && isEnabled(tick, marking_)) break;
    bool progress = false;
    for (size_t t = 0; t < net_.transitions.size(); ++t) {
      if (static_cast<int>(t) == tick_transition) continue;
      const Transition& transition = net_.transitions[t];
      if (!isEnabled(transition, marking_)) continue;
      if (transition.silent()) {
        consumeInputs(transition, marking_);
        produceOutputs(transition, marking_);
        ++silent_firings;
        progress = true;
      } else if (!experts_[transition_expert_[t]].running) {
        startFiring(static_cast<int>(t), 1, tick_, false);  // sent after the step's MARKING
        note("fire " + transition.expert);
        progress = true;
      }
    }
    // The tick closes when nothing else can start.
    if (!progress && !endingAtTickEnd() && isEnabled(tick, marking_)) {
      if (!nextTickMayStart()) {
        tick_waits = true;
        if (held_) note("held after tick " + std::to_string(tick_));
        break;
      }
      consumeInputs(tick, marking_);
      produceOutputs(tick, marking_);
      ++tick_;
      ++stats_.ticks_completed;
      ++silent_firings;
      note("tick " + std::to_string(tick_));
      tick_opened = true;
      progress = true;
    }
    if (silent_firings > config_.max_silent_firings_per_step) {
      publishMarking(text);
      unsent_fires_.clear();
      fail("silent transitions fired " + std::to_string(silent_firings) +
           " times without any expert running: the net has a cycle without an expert");
      return;
    }
    if (!progress) break;
  }
  // The MARKING first: the run's log then always holds the state a FIRE
  // came from, which is what a restarted arbiter resumes from. The new
  // tick's status after its first FIREs: they are what the experts wait for.
  publishMarking(text);
  for (int e : unsent_fires_) sendFire(e);
  unsent_fires_.clear();
  if (tick_opened) sendStatus(beft::run_status_t::STATE_RUNNING, "tick " + std::to_string(tick_));
  if (held_ && !was_held) noteHeld();
  if (anyRunning()) return;
  if (endingAtTickEnd() && isEnabled(tick, marking_)) {
    const int64_t ticks = tick_ + 1;
    ++stats_.ticks_completed;
    finish(stop_requested_ ? "stopped on request after " + std::to_string(ticks) + " ticks: " + stop_reason_
                           : "finished after " + std::to_string(ticks) + " ticks");
    return;
  }
  if (tick_waits) return;  // not a deadlock: the tick transition is enabled
  fail("deadlock in tick " + std::to_string(tick_) +
       ": no transition is enabled and no expert is running; marking: " +
       describeMarking(net_, marking_));
}

bool ArbiterCore::nextTickMayStart() {
  if (control_.holdsAfter(tick_)) {
    held_ = true;
    pace_wait_.reset();
    return false;
  }
  const double earliest = pace_.earliestStart(tick_ + 1);
  if (clock_.now() < earliest) {
    pace_wait_ = earliest;
    return false;
  }
  pace_wait_.reset();
  return true;
}

void ArbiterCore::noteHeld() {
  const bool paused = control_.requestedMode() == beft::run_control_t::MODE_PAUSE;
  const std::string what = (paused ? "paused after tick " : "held after tick ") + std::to_string(tick_) +
                           (paused ? "" : " (stepped)") + ", as " + control_.origin() + " asked";
  log::info("run ", what, ": the next tick waits for RUN_CONTROL");
  sendStatus(beft::run_status_t::STATE_RUNNING, "tick " + std::to_string(tick_) + ", " + what);
  sendControlState();
}

void ArbiterCore::onRunControl(const beft::run_control_t& request) {
  if (ended()) return;
  const RunControl::Outcome outcome = control_.apply(request, tick_);
  if (outcome == RunControl::Outcome::kRefused) {
    if (last_refused_ != std::make_pair(request.origin, request.sequence))
      log::warn("RUN_CONTROL from '", request.origin, "' (sequence ", request.sequence, ") refused: ",
                control_.refusal());
    last_refused_ = {request.origin, request.sequence};
    return;
  }
  if (outcome == RunControl::Outcome::kOld || outcome == RunControl::Outcome::kRepeated) {
    // Its answer may have been lost, or overtaken by another origin's: answer this origin.
    output_.sendRunControlState(control_.answerTo(request.origin, tick_, held_));
    return;
  }
  const int8_t mode = control_.requestedMode();
  log::info("RUN_CONTROL from ", control_.origin(), " (sequence ", control_.sequence(), "): ",
            mode == beft::run_control_t::MODE_RUN     ? std::string("run")
            : mode == beft::run_control_t::MODE_PAUSE ? "pause after tick " + std::to_string(control_.holdAfterTick())
                                                      : "step: hold after tick " + std::to_string(control_.holdAfterTick()),
            " (at tick ", tick_, held_ ? ", held" : "", ")");
  if (held_ && !control_.holdsAfter(tick_)) {
    held_ = false;
    pace_.restart(clock_.now(), tick_ + 1);  // real time counts from the resume
    sendControlState();
    step("resumed by " + control_.origin());
    return;
  }
  sendControlState();
  // Waiting for the pace when a pause came: hold at once.
  if (pace_wait_ && state_ == RunState::Running && control_.holdsAfter(tick_)) step("paused by " + control_.origin());
}

void ArbiterCore::sendControlState() {
  beft::run_control_t state = controlState();
  output_.sendRunControlState(state);
  next_control_state_ = clock_.now() + config_.control_state_period_s;
}

bool ArbiterCore::endingAtTickEnd() const {
  return stop_requested_ || (config_.max_ticks > 0 && tick_ + 1 >= config_.max_ticks);
}

void ArbiterCore::notePublished(const beft::done_t& done) {
  if (done.sender == 0) return;
  const std::size_t count = std::min(done.published_channels.size(), done.published_sequences.size());
  for (std::size_t i = 0; i < count; ++i)
    frontier_changes_[{done.sender, done.published_channels[i]}] = done.published_sequences[i];
}

// Before a firing starts: what has been published since the last FRONTIER
// message goes out, and the firing comes after it.
void ArbiterCore::sendFrontierChanges() {
  if (frontier_changes_.empty()) return;
  beft::frontier_t frontier;
  frontier.utime = 0;
  for (const auto& [where, sequence] : frontier_changes_) {
    frontier.senders.push_back(where.first);
    frontier.channels.push_back(where.second);
    frontier.sequences.push_back(sequence);
  }
  frontier.count = static_cast<int32_t>(frontier.senders.size());
  frontier_changes_.clear();
  const FrontierMark sent = output_.sendFrontier(frontier);
  if (sent.sequence > 0) frontier_ = sent;
}

void ArbiterCore::startFiring(int transition, int attempt, int64_t tick, bool send_now) {
  const int e = transition_expert_[transition];
  if (attempt == 1) consumeInputs(net_.transitions[transition], marking_);
  sendFrontierChanges();
  Running running;
  running.after = frontier_;
  running.transition = transition;
  running.firing_id = next_firing_id_++;
  running.tick = tick;
  running.attempt = attempt;
  running.attempt_start = clock_.now();
  experts_[e].running = running;
  ++stats_.firings_started;
  if (send_now) sendFire(e);
  else unsent_fires_.push_back(e);
}

void ArbiterCore::sendFire(int e) {
  Running& running = *experts_[e].running;
  beft::fire_t fire = control::makeFire(experts_[e].name, net_.transitions[running.transition].id, running.tick,
                                        utimeOfTick(running.tick), running.firing_id);
  fire.after_sender = running.after.sender;
  fire.after_frontier = running.after.sequence;
  running.last_send = clock_.now();
  output_.sendFire(fire);
}

void ArbiterCore::completeFiring(int e, const beft::done_t& done) {
  const Running running = *experts_[e].running;
  if (done.tick != running.tick)
    log::warn("DONE from ", done.expert, " for firing ", done.firing_id, " says tick ", done.tick,
              ", the firing was for tick ", running.tick, " (accepted by firing id)");
  if (done.outcome == beft::done_t::OUTCOME_OK) {
    output_.firingEnded(recordOf(e, "ok", "", done.message, done.duration));
    produceOutputs(net_.transitions[running.transition], marking_);
    endFiring(e, true);
    ++stats_.firings_done;
    return;
  }
  applyPolicy(e, net_.transitions[running.transition].policy.on_failure, "failed",
              done.message.empty() ? "the expert reported a failure" : "failed: " + done.message,
              done.duration);
}

void ArbiterCore::applyPolicy(int e, ExpiryAction action, const std::string& outcome,
                              const std::string& reason, double expert_duration_s) {
  const Running running = *experts_[e].running;
  const Transition& transition = net_.transitions[running.transition];
  const FiringPolicy& policy = transition.policy;
  const std::string what = describeFiring(running, e) + ": " + reason;
  if (stop_requested_) {  // the run is asked to end: no retry, no waiting on a broken tick
    output_.firingEnded(recordOf(e, outcome, "stop", reason, expert_duration_s));
    endFiring(e, false);
    finish("stopped on request in tick " + std::to_string(tick_) + " (" + stop_reason_ +
           "), which could not complete: " + what);
    return;
  }
  if (action == ExpiryAction::Retry && running.attempt <= policy.retries) {
    output_.firingEnded(recordOf(e, outcome, "retry", reason, expert_duration_s));
    endFiring(e, false);
    ++stats_.retries;
    log::warn(what, "; retry ", running.attempt, " of ", policy.retries);
    startFiring(running.transition, running.attempt + 1, running.tick);
    return;
  }
  const ExpiryAction effective = action == ExpiryAction::Retry ? policy.after_retries : action;
  const std::string after =
      action == ExpiryAction::Retry ? " (after " + std::to_string(policy.retries) + " retries)" : "";
  if (effective == ExpiryAction::Skip) {
    output_.firingEnded(recordOf(e, outcome, "skip", reason, expert_duration_s));
    produceOutputs(transition, marking_);
    endFiring(e, false);
    ++stats_.skips;
    log::warn(what, after, "; skipped as the net says: the run goes on as if it were done");
    return;
  }
  output_.firingEnded(recordOf(e, outcome, "fail", reason, expert_duration_s));
  endFiring(e, false);
  fail(what + after + "; the net's policy for transition " + transition.id + " is to fail the run");
}

void ArbiterCore::endFiring(int e, bool completed) {
  const int64_t id = experts_[e].running->firing_id;
  recently_ended_[id] = EndedFiring{e, completed};
  while (recently_ended_.size() > kEndedWindow) recently_ended_.erase(recently_ended_.begin());
  experts_[e].running.reset();
}

FiringRecord ArbiterCore::recordOf(int e, const std::string& outcome, const std::string& action,
                                   const std::string& message, double expert_duration_s) const {
  const Running& running = *experts_[e].running;
  FiringRecord record;
  record.tick = running.tick;
  record.firing_id = running.firing_id;
  record.expert = experts_[e].name;
  record.transition = net_.transitions[running.transition].id;
  record.attempt = running.attempt;
  record.start_s = running.attempt_start - run_start_;
  record.duration_s = clock_.now() - running.attempt_start;
  record.expert_duration_s = expert_duration_s;
  record.outcome = outcome;
  record.action = action;
  record.message = message;
  return record;
}

void ArbiterCore::fail(const std::string& why) { endRun(RunState::Failed, why); }

void ArbiterCore::finish(const std::string& why) { endRun(RunState::Finished, why); }

void ArbiterCore::endRun(RunState state, const std::string& why) {
  if (ended()) return;
  const bool started_ticks = state_ == RunState::Running;
  state_ = state;
  message_ = why;
  for (size_t e = 0; e < experts_.size(); ++e) {
    if (!experts_[e].running) continue;
    output_.firingEnded(recordOf(static_cast<int>(e), "abandoned", "", "the run ended", -1.0));
    endFiring(static_cast<int>(e), false);
  }
  if (state == RunState::Failed && started_ticks) log::error("run FAILED in tick ", tick_, ": ", why);
  else if (state == RunState::Failed) log::error("run FAILED before the first tick: ", why);
  else log::info("run FINISHED: ", why);
  sendStatus(state == RunState::Finished ? beft::run_status_t::STATE_FINISHED
                                         : beft::run_status_t::STATE_FAILED,
             why);
  final_sends_left_ = std::max(0, config_.final_status_repeats - 1);
  next_final_send_ = clock_.now() + config_.final_status_period_s;
}

void ArbiterCore::sendStatus(int8_t state, const std::string& message) {
  output_.sendRunStatus(control::makeRunStatus(state, tick_, utimeOfTick(tick_), message));
}

void ArbiterCore::publishMarking(const std::string& event) {
  beft::marking_t marking{};
  marking.utime = utimeOfTick(tick_);
  marking.tick = tick_;
  marking.step = ++stats_.steps;
  marking.event = event;
  marking.num_places = static_cast<int32_t>(net_.places.size());
  marking.place_ids.reserve(net_.places.size());
  for (const auto& place : net_.places) marking.place_ids.push_back(place.id);
  marking.tokens.assign(marking_.begin(), marking_.end());
  for (const auto& expert : experts_)
    if (expert.running) marking.running.push_back(expert.name);
  marking.num_running = static_cast<int32_t>(marking.running.size());
  output_.sendMarking(marking);
}

bool ArbiterCore::anyRunning() const {
  for (const auto& expert : experts_)
    if (expert.running) return true;
  return false;
}

double ArbiterCore::heartbeatTimeout(const Transition& transition) const {
  return transition.policy.heartbeat_timeout_s > 0.0 ? transition.policy.heartbeat_timeout_s
                                                     : config_.heartbeat_timeout_s;
}

int ArbiterCore::expertIndex(const std::string& name) const {
  for (size_t i = 0; i < experts_.size(); ++i)
    if (experts_[i].name == name) return static_cast<int>(i);
  return -1;
}

int64_t ArbiterCore::utimeOfTick(int64_t tick) const {
  return static_cast<int64_t>(std::llround(static_cast<double>(tick) * config_.dt_s * 1e6));
}

std::string ArbiterCore::describeFiring(const Running& running, int e) const {
  std::string text = experts_[e].name + " (tick " + std::to_string(running.tick) + ", firing " +
                     std::to_string(running.firing_id);
  if (running.attempt > 1) text += ", attempt " + std::to_string(running.attempt);
  return text + ")";
}

}  // namespace beft::arbiter

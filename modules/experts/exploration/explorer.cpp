#include "experts/exploration/explorer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "experts/exploration/cheapest_first.hpp"

namespace beft::exploration {
namespace {

const char* kVerifyKind = "verify";
const char* kExploreKind = "explore";

std::string fixed(double value, int decimals = 1) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string at(double x, double y) { return "(" + fixed(x) + ", " + fixed(y) + ")"; }

double wrapDeg(double deg) {
  deg = std::fmod(deg + 180.0, 360.0);
  if (deg < 0) deg += 360.0;
  return deg - 180.0;
}

bool contains(const std::vector<int64_t>& ids, int64_t id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

TaskRequest subTask(const std::string& kind, double x, double y, double yaw, const std::string& object_id,
                    const std::string& note) {
  TaskRequest request;
  request.type = TaskRequest::Type::Push;
  request.kind = kind;
  request.x = x;
  request.y = y;
  request.yaw = yaw;
  request.object_id = object_id;
  request.note = note;
  return request;
}

}  // namespace

Explorer::Explorer(ExplorerParameters parameters)
    : parameters_(std::move(parameters)), memory_(parameters_.frontiers), close_looks_(parameters_.close_looks) {}

Explorer::Phase Explorer::phase() const {
  if (stopped_) return Phase::Stopped;
  if (!job_) return Phase::Idle;
  switch (job_->kind) {
    case JobKind::LookAround: return Phase::LookAround;
    case JobKind::Verify:
    case JobKind::Inspect: return Phase::Verify;
    case JobKind::Explore:
    case JobKind::CloseLook: return Phase::Explore;
  }
  return Phase::Idle;
}

int Explorer::attempts(const std::string& object_id) const {
  const auto it = targets_.find(object_id);
  return it == targets_.end() ? 0 : it->second.attempts;
}

bool Explorer::givenUp(const std::string& object_id) const {
  const auto it = targets_.find(object_id);
  return it != targets_.end() && it->second.given_up;
}

const std::vector<Point>& Explorer::triedViewpoints(const std::string& object_id) const {
  static const std::vector<Point> none;
  const auto it = targets_.find(object_id);
  return it == targets_.end() ? none : it->second.tried;
}

bool Explorer::wantsVerify(const HypothesisView& h) const { return h.heard && !h.verified && !h.falsified; }

bool Explorer::wantsVerifyNow(const HypothesisView& h, bool not_located_too) const {
  return wantsVerify(h) && (h.located || not_located_too || !parameters_.verify_located_first);
}

bool Explorer::wantsInspect(const HypothesisView& h) const {
  return parameters_.inspect_glimpsed && h.glimpsed && !h.heard && !h.seen &&
         h.person_confidence >= h.confidence - parameters_.inspect_person_margin;
}

const HypothesisView* Explorer::findHypothesis(const Observation& o, const std::string& id) const {
  for (const auto& h : o.hypotheses)
    if (h.object_id == id) return &h;
  return nullptr;
}

const KnownMap* Explorer::knownMap(const Observation& o) {
  if (!o.map) return nullptr;
  const double radius = o.robot_radius + parameters_.safety_margin_m;
  if (!map_ || map_version_ != o.map_version || map_radius_ != radius) {
    // The map known before goes along: the standing grid is then inflated
    // again only where the map changed.
    map_ = map_ ? std::make_unique<KnownMap>(*o.map, radius, std::move(*map_)) : std::make_unique<KnownMap>(*o.map, radius);
    map_version_ = o.map_version;
    map_radius_ = radius;
  }
  return map_.get();
}

void Explorer::lookClosely(const Observation& o) {
  if (!parameters_.close_looks.enabled) return;
  if (const KnownMap* map = knownMap(o)) close_looks_.look(*map, o.robot_x, o.robot_y, o.robot_yaw + o.head_yaw);
}

void Explorer::updateTrail(const Observation& o) {
  const auto& stood = memory_.stood();
  if (stood.empty() ||
      std::hypot(stood.back().x - o.robot_x, stood.back().y - o.robot_y) >= parameters_.stood_spacing_m)
    memory_.addStood({o.robot_x, o.robot_y});
}

bool Explorer::wantsMap(double t) const {
  if (stopped_) return false;
  if (!job_) return true;
  return job_->composite_id != 0 && t - job_->last_check_t >= parameters_.revalidate_period_s;
}

Decision Explorer::step(const Observation& o) {
  Decision d;
  if (stopped_) {
    d.stop = stop_reason_;
    return d;
  }
  if (!o.robot_known) return d;  // nothing sensible to decide yet
  updateTrail(o);
  lookClosely(o);
  finishStrayComposites(o, d);
  if (o.duration > 0 && o.t >= o.duration) {
    if (job_) endJob(o, d, false, "the scenario's duration ended", true);
    stop("the scenario's duration of " + fixed(o.duration) + " s is reached", d);
    return d;
  }
  if (job_) followJob(o, d);
  if (!job_ && !stopped_ && (o.t >= idle_until_t_ || hasFreshTarget(o))) decide(o, d);
  return d;
}

bool Explorer::reconsiderMoved(const Observation& o, Decision& d) {
  if (!(parameters_.moved_m > 0)) return false;
  bool any = false;
  for (const auto& h : o.hypotheses) {
    const auto it = targets_.find(h.object_id);
    if (it == targets_.end() || !it->second.given_up || !it->second.given_up_at || !wantsVerify(h)) continue;
    TargetMemory& memory = it->second;
    const double moved = std::hypot(h.x - memory.given_up_at->x, h.y - memory.given_up_at->y);
    if (moved < parameters_.moved_m || memory.tries_after_moving >= parameters_.tries_after_moving) continue;
    const int tries = memory.tries_after_moving + 1;
    d.log.push_back(h.object_id + ": now placed " + fixed(moved) + " m from where it was given up (" +
                    at(memory.given_up_at->x, memory.given_up_at->y) + "): tried again (" + std::to_string(tries) +
                    " of " + std::to_string(parameters_.tries_after_moving) + ")");
    memory = TargetMemory{};
    memory.tries_after_moving = tries;
    any = true;
  }
  return any;
}

double Explorer::movedMoreThanTheRobot(const HypothesisView& h, const TargetMemory& memory, const Observation& o) {
  const double target_moved = std::hypot(h.x - memory.tried_at->x, h.y - memory.tried_at->y);
  const double robot_moved = std::hypot(o.robot_x - memory.robot_at_try.x, o.robot_y - memory.robot_at_try.y);
  return target_moved - robot_moved;
}

bool Explorer::placedFarFromItsTries(const HypothesisView& h, const TargetMemory& memory, const Observation& o) const {
  if (!(parameters_.moved_m > 0) || memory.given_up || !memory.tried_at) return false;
  return movedMoreThanTheRobot(h, memory, o) >= parameters_.moved_m &&
         memory.tries_after_moving < parameters_.tries_after_moving;
}

void Explorer::tryAfreshIfMoved(const HypothesisView& h, TargetMemory& memory, const Observation& o, Decision& d) {
  if (!placedFarFromItsTries(h, memory, o)) return;
  const int tries = memory.tries_after_moving + 1;
  d.log.push_back(h.object_id + ": now placed " + fixed(std::hypot(h.x - memory.tried_at->x, h.y - memory.tried_at->y)) +
                  " m from where its viewpoints were tried (" + at(memory.tried_at->x, memory.tried_at->y) +
                  "), the robot " + fixed(std::hypot(o.robot_x - memory.robot_at_try.x, o.robot_y - memory.robot_at_try.y)) +
                  " m from where it was: tried afresh (" + std::to_string(tries) + " of " +
                  std::to_string(parameters_.tries_after_moving) + ")");
  memory = TargetMemory{};
  memory.tries_after_moving = tries;
}

void Explorer::noteFirstTry(TargetMemory& memory) const {
  if (memory.tried_at || !job_) return;
  memory.tried_at = job_->target;
  if (!memory_.stood().empty()) memory.robot_at_try = memory_.stood().back();
}

void Explorer::giveUp(TargetMemory& memory) {
  memory.given_up = true;
  if (job_ && (job_->kind == JobKind::Verify || job_->kind == JobKind::Inspect)) memory.given_up_at = job_->target;
}

bool Explorer::hasFreshTarget(const Observation& o) const {
  for (const auto& h : o.hypotheses) {
    if (!wantsVerify(h) && !wantsInspect(h)) continue;
    const auto it = targets_.find(h.object_id);
    if (it == targets_.end() || (!it->second.given_up && !it->second.no_viewpoint)) return true;
  }
  return false;
}

// Composites of ours on the stack that no job follows (an earlier job's whose
// finish was lost, or one whose push was confirmed too late): finish them.
void Explorer::finishStrayComposites(const Observation& o, Decision& d) {
  for (const auto& entry : o.stack) {
    if (entry.origin != parameters_.origin || entry.parent != 0) continue;
    if (job_ && entry.id == job_->composite_id) continue;
    const bool awaited = job_ && job_->composite_id == 0 && !contains(known_task_ids_, entry.id);
    if (awaited || contains(finish_sent_, entry.id)) continue;
    TaskRequest finish;
    finish.type = TaskRequest::Type::Finish;
    finish.task_id = entry.id;
    finish.success = false;
    finish.reason = "no longer pursued";
    d.requests.push_back(finish);
    finish_sent_.push_back(entry.id);
  }
}

void Explorer::followJob(const Observation& o, Decision& d) {
  Job& job = *job_;
  if (job.composite_id == 0) return awaitCompositeId(o, d);  // waiting to learn the id the stack gave our composite
  const bool on_stack = std::any_of(o.stack.begin(), o.stack.end(),
                                    [&](const StackEntry& e) { return e.id == job.composite_id; });
  int sub_tasks = 0;
  for (const auto& entry : o.stack)
    if (entry.parent == job.composite_id) ++sub_tasks;
  if (endIfSettledOrGone(o, d, on_stack)) return;
  if (endIfInterrupted(o, d)) return;
  if (endIfLookedOrLate(o, d, sub_tasks)) return;
  revalidate(o, d);
}

void Explorer::awaitCompositeId(const Observation& o, Decision& d) {
  Job& job = *job_;
  const std::string composite_kind = (job.kind == JobKind::Verify || job.kind == JobKind::Inspect) ? kVerifyKind : kExploreKind;
  for (const auto& entry : o.stack) {
    if (entry.origin == parameters_.origin && entry.parent == 0 && entry.kind == composite_kind &&
        entry.object_id == job.object_id && !contains(known_task_ids_, entry.id)) {
      job.composite_id = entry.id;
      job.sub_tasks_pushed_t = o.t;
      known_task_ids_.push_back(entry.id);
      for (auto sub : job.sub_tasks) {
        sub.parent = entry.id;
        d.requests.push_back(sub);
      }
      return;
    }
  }
  if (o.t - job.pushed_t > parameters_.confirm_timeout_s) {
    if (job.kind == JobKind::Verify || job.kind == JobKind::Inspect)
      recordFailedAttempt(job.object_id, {job.x, job.y}, "its task never showed on the stack", d);
    endJob(o, d, false, "the task never showed on the stack", false);
  }
}

// A verify or inspect job ends when its hypothesis is settled; any job ends
// when the stack ended its task. True if the job ended.
bool Explorer::endIfSettledOrGone(const Observation& o, Decision& d, bool on_stack) {
  Job& job = *job_;
  if (job.kind == JobKind::Verify || job.kind == JobKind::Inspect) {
    const HypothesisView* h = findHypothesis(o, job.object_id);
    if (h != nullptr) {
      const bool settled = job.kind == JobKind::Verify ? (h->verified || h->falsified) : (h->seen || h->heard);
      if (settled) {
        const std::string what = h->verified ? "verified" : h->falsified ? "falsified" : h->seen ? "seen" : "heard";
        endJob(o, d, true, job.object_id + " " + what, on_stack);
        return true;
      }
    }
    if (!on_stack) {  // the stack ended it: a sub-task failed, or it was removed
      recordFailedAttempt(job.object_id, {job.x, job.y}, "the task ended before it was settled", d);
      endJob(o, d, false, "the task ended on the stack before " + job.object_id + " was settled", false);
      return true;
    }
  } else if (!on_stack) {
    if (job.kind == JobKind::Explore) memory_.addVisited({job.x, job.y});
    if (job.kind == JobKind::CloseLook) closeLookVisited(o, job);
    endJob(o, d, false, "the task ended on the stack", false);
    return true;
  }
  return false;
}

// Exploring gives way to a hypothesis to verify; looking closely, also to a
// glimpsed possible person to inspect (what it is for). True if the job ended.
bool Explorer::endIfInterrupted(const Observation& o, Decision& d) {
  if (job_->kind != JobKind::Explore && job_->kind != JobKind::CloseLook) return false;
  const bool for_inspect = job_->kind == JobKind::CloseLook;
  for (const auto& h : o.hypotheses) {
    const bool verify = wantsVerifyNow(h, false), inspect = for_inspect && wantsInspect(h);
    if (!verify && !inspect) continue;
    const auto it = targets_.find(h.object_id);
    // Only a hypothesis not known to lack a viewpoint: those wait for this job to end.
    const bool available = it == targets_.end() || (!it->second.given_up && !it->second.no_viewpoint);
    if (!available) continue;
    endJob(o, d, true, "interrupted: " + h.object_id + (verify ? " to verify" : " to inspect"), true);
    return true;
  }
  return false;
}

// The stack seen now has applied the sub-tasks pushed at an earlier step:
// none left means the robot got there and looked. Past its deadline a job
// fails. True if the job ended (or waits out its look).
bool Explorer::endIfLookedOrLate(const Observation& o, Decision& d, int sub_tasks) {
  Job& job = *job_;
  if (sub_tasks == 0 && o.t > job.sub_tasks_pushed_t) {
    if (job.done_looking_t < 0) job.done_looking_t = o.t;
    switch (job.kind) {
      case JobKind::LookAround: endJob(o, d, true, "looked around", true); return true;
      case JobKind::Explore:
        memory_.addVisited({job.x, job.y});
        endJob(o, d, true, "frontier at " + at(job.x, job.y) + " reached", true);
        return true;
      case JobKind::CloseLook:
        closeLookVisited(o, job);
        endJob(o, d, true, "looked closely from " + at(job.x, job.y), true);
        return true;
      case JobKind::Verify:
      case JobKind::Inspect:
        if (o.t - job.done_looking_t >= parameters_.look_dwell_s) {
          const std::string why = "still not settled after looking from " + at(job.x, job.y);
          recordFailedAttempt(job.object_id, {job.x, job.y}, why, d);
          TargetMemory& memory = targets_[job.object_id];
          const auto in_plain_view = job.kind == JobKind::Verify && parameters_.give_up_in_plain_view &&
                                             !memory.given_up ? estimateInPlainView(o, job.object_id)
                                                              : std::nullopt;
          if (in_plain_view) {
            giveUp(memory);
            memory.why = "given up: nothing where it was heard, " + at(in_plain_view->x, in_plain_view->y) +
                         ", in plain view from " + at(o.robot_x, o.robot_y);
            d.log.push_back(job.object_id + ": " + memory.why);
          }
          endJob(o, d, false, why, true);
        }
        return true;
    }
  }
  if (o.t > job.deadline_t) {
    if (job.kind == JobKind::Verify || job.kind == JobKind::Inspect)
      recordFailedAttempt(job.object_id, {job.x, job.y}, "timed out", d);
    if (job.kind == JobKind::Explore) memory_.addVisited({job.x, job.y});
    if (job.kind == JobKind::CloseLook) closeLookVisited(o, job);
    endJob(o, d, false, "timed out", true);
    return true;
  }
  return false;
}

void Explorer::revalidate(const Observation& o, Decision& d) {
  Job& job = *job_;
  if (o.t - job.last_check_t < parameters_.revalidate_period_s) return;
  job.last_check_t = o.t;
  std::string why;
  if (jobStillValid(o, why)) return;
  // What the map showed on the way rules the viewpoint out. Until the target
  // was first looked at from somewhere, that is not an attempt (a target
  // behind walls being mapped piece by piece is not given up for it); after,
  // it is one more way of seeing it that failed. But a target that jumped
  // far from where its viewpoints were tried is tried afresh at its next
  // start: this viewpoint, chosen for the old place, is no failure at the
  // new one.
  if (job.kind == JobKind::Verify || job.kind == JobKind::Inspect) {
    const HypothesisView* h = findHypothesis(o, job.object_id);
    TargetMemory& memory = targets_[job.object_id];
    if (h != nullptr && placedFarFromItsTries(*h, memory, o)) d.log.push_back(job.object_id + ": " + why);
    else if (memory.attempts == 0)
      recordRuledOut(job.object_id, {job.x, job.y}, why, surroundingsBeingMapped(o, job.object_id), d);
    else recordFailedAttempt(job.object_id, {job.x, job.y}, why, d);
  }
  if (job.kind == JobKind::Explore) memory_.addVisited({job.x, job.y});
  // A close look's goal seen closely on the way is done; one now blocked
  // is not chosen again (only standable cells are).
  endJob(o, d, job.kind == JobKind::Explore || job.kind == JobKind::CloseLook, why, true);
}

ViewpointParameters Explorer::viewpointsFor(const HypothesisView& h) const {
  ViewpointParameters viewpoints = parameters_.viewpoints;
  if (h.best_category == "car") viewpoints.own_extent_m = std::max(viewpoints.own_extent_m, parameters_.car_extent_m);
  if (h.best_category == "fire") viewpoints.own_extent_m = std::max(viewpoints.own_extent_m, parameters_.fire_extent_m);
  return viewpoints;
}

bool Explorer::jobStillValid(const Observation& o, std::string& why) {
  const Job& job = *job_;
  const KnownMap* map = knownMap(o);
  if (map == nullptr || job.kind == JobKind::LookAround) return true;
  if (job.kind == JobKind::Explore) {
    if (!frontierNear(*map, memory_, job.x, job.y, parameters_.frontier_check_radius_m)) {
      why = "frontier at " + at(job.x, job.y) + " revealed";
      return false;
    }
    return true;
  }
  if (job.kind == JobKind::CloseLook) {
    Cell cell;
    const CloseLookParameters& looks = parameters_.close_looks;
    if (close_looks_.openGroundNear(*map, job.x, job.y, looks.range_m) < looks.min_cells) {
      why = "the ground around " + at(job.x, job.y) + " was looked at closely on the way";
      return false;
    }
    if (!map->cellOf(job.x, job.y, cell) || !map->standable(cell.x, cell.y)) {
      why = "the close look's goal " + at(job.x, job.y) + " is blocked on the map";
      return false;
    }
    return true;
  }
  const HypothesisView* h = findHypothesis(o, job.object_id);
  if (h == nullptr) return true;
  const double distance = std::hypot(h->x - job.x, h->y - job.y);
  if (distance > parameters_.viewpoints.max_distance_m + 1.0 || distance < parameters_.viewpoints.min_distance_m * 0.5) {
    why = job.object_id + " moved: " + fixed(distance) + " m from the viewpoint";
    return false;
  }
  Cell cell;
  if (!map->cellOf(job.x, job.y, cell) || !map->standable(cell.x, cell.y)) {
    why = "the viewpoint " + at(job.x, job.y) + " is blocked on the map";
    return false;
  }
  const ViewpointParameters viewpoints = viewpointsFor(*h);
  const TargetCells own = targetCells(*map, h->x, h->y, viewpoints);
  if (!inLineOfSight(*map, job.x, job.y, h->x, h->y, viewpoints, nullptr, &own)) {
    why = "an obstacle now blocks the view of " + job.object_id + " from " + at(job.x, job.y);
    return false;
  }
  return true;
}

void Explorer::recordFailedAttempt(const std::string& object_id, const Point& viewpoint, const std::string& why,
                                   Decision& d) {
  TargetMemory& memory = targets_[object_id];
  noteFirstTry(memory);
  ++memory.attempts;
  memory.tried.push_back(viewpoint);
  const Job* job = job_ ? &*job_ : nullptr;
  const int limit = job != nullptr && job->kind == JobKind::Inspect ? parameters_.inspect_attempts
                                                                    : parameters_.verify_attempts;
  d.log.push_back(object_id + ": attempt " + std::to_string(memory.attempts) + " failed (" + why + ")");
  memory.why = "attempt " + std::to_string(memory.attempts) + " failed (" + why + ")";
  if (memory.attempts >= limit) {
    giveUp(memory);
    memory.why = "given up after " + std::to_string(memory.attempts) + " viewpoints, the last: " + why;
    d.log.push_back(object_id + ": given up after " + std::to_string(memory.attempts) + " viewpoints");
  }
}

std::optional<Point> Explorer::estimateInPlainView(const Observation& o, const std::string& object_id) {
  const KnownMap* map = knownMap(o);
  const HypothesisView* h = findHypothesis(o, object_id);
  // A point along a bearing at an assumed range is no place: the source may be farther on.
  if (map == nullptr || h == nullptr || !h->located) return std::nullopt;
  if (std::hypot(h->x - o.robot_x, h->y - o.robot_y) > parameters_.viewpoints.max_distance_m) return std::nullopt;
  const double bearing = std::atan2(h->y - o.robot_y, h->x - o.robot_x) * 180.0 / M_PI;
  if (std::abs(wrapDeg(bearing - o.robot_yaw - o.head_yaw)) > parameters_.close_looks.fov_deg / 2) return std::nullopt;
  const ViewpointParameters viewpoints = viewpointsFor(*h);
  const TargetCells own = targetCells(*map, h->x, h->y, viewpoints);
  double unknown_m = 0;
  if (!inLineOfSight(*map, o.robot_x, o.robot_y, h->x, h->y, viewpoints, &unknown_m, &own) || unknown_m > 0)
    return std::nullopt;
  return Point{h->x, h->y};
}

bool Explorer::surroundingsBeingMapped(const Observation& o, const std::string& object_id) {
  const KnownMap* map = knownMap(o);
  const HypothesisView* h = findHypothesis(o, object_id);
  return map != nullptr && h != nullptr && frontierNear(*map, memory_, h->x, h->y, parameters_.viewpoints.max_distance_m);
}

// A house mapped wall by wall rules out one viewpoint outside a closed side
// after another before the robot has seen its open side: those do not count
// until the walls around the target are mapped (or too many were).
void Explorer::recordRuledOut(const std::string& object_id, const Point& viewpoint, const std::string& why,
                              bool while_mapping, Decision& d) {
  TargetMemory& memory = targets_[object_id];
  noteFirstTry(memory);
  ++memory.ruled_out;
  memory.tried.push_back(viewpoint);
  d.log.push_back(object_id + ": viewpoint " + at(viewpoint.x, viewpoint.y) + " ruled out (" + why + ")");
  memory.why = "viewpoint " + at(viewpoint.x, viewpoint.y) + " ruled out (" + why + ")";
  if (while_mapping && memory.ruled_out_while_mapping < parameters_.ruled_out_while_mapping) {
    ++memory.ruled_out_while_mapping;
    return;
  }
  if (memory.ruled_out - memory.ruled_out_while_mapping >= parameters_.ruled_out_viewpoints) {
    giveUp(memory);
    const std::string count =
        std::to_string(memory.ruled_out) + " viewpoints ruled out" +
        (memory.ruled_out_while_mapping > 0
             ? " (" + std::to_string(memory.ruled_out_while_mapping) + " while its surroundings were being mapped)"
             : "");
    memory.why = "given up after " + count + ", the last: " + why;
    d.log.push_back(object_id + ": given up after " + count);
  }
}

void Explorer::endJob(const Observation& o, Decision& d, bool success, const std::string& reason,
                      bool finish_on_stack) {
  (void)o;
  Job& job = *job_;
  if (finish_on_stack && job.composite_id != 0 && !contains(finish_sent_, job.composite_id)) {
    TaskRequest finish;
    finish.type = TaskRequest::Type::Finish;
    finish.task_id = job.composite_id;
    finish.success = success;
    finish.reason = reason;
    d.requests.push_back(finish);
    finish_sent_.push_back(job.composite_id);
  } else if (job.composite_id != 0) {
    finish_sent_.push_back(job.composite_id);  // gone already: never finish it later
  }
  if (job.kind == JobKind::LookAround) looked_around_ = true;
  d.log.push_back((success ? "done: " : "ended: ") + reason);
  job_.reset();
}

void Explorer::stop(const std::string& reason, Decision& d) {
  stopped_ = true;
  stop_reason_ = reason;
  d.stop = reason;
  d.log.push_back("stop: " + reason);
}

void Explorer::startJob(Job job, const std::string& note, int32_t priority, const Observation& o, Decision& d) {
  TaskRequest composite;
  composite.type = TaskRequest::Type::Push;
  composite.kind = (job.kind == JobKind::Verify || job.kind == JobKind::Inspect) ? kVerifyKind : kExploreKind;
  composite.object_id = job.object_id;
  composite.priority = priority;
  composite.x = job.x;
  composite.y = job.y;
  composite.yaw = job.yaw;
  composite.note = note;
  d.requests.push_back(composite);
  d.log.push_back("start: " + note);
  job.pushed_t = o.t;
  job.last_check_t = o.t;
  job_ = std::move(job);
}

void Explorer::decide(const Observation& o, Decision& d) {
  if (parameters_.look_around && !looked_around_) {
    Job job;
    job.kind = JobKind::LookAround;
    job.x = o.robot_x;
    job.y = o.robot_y;
    job.yaw = o.robot_yaw;
    // Sub-tasks run in the order they are pushed.
    for (int quarter = 1; quarter <= 4; ++quarter)
      job.sub_tasks.push_back(subTask("turn", 0, 0, wrapDeg(o.robot_yaw + 90.0 * quarter), "",
                                      "look around, " + std::to_string(90 * quarter) + " deg"));
    job.deadline_t = o.t + parameters_.attempt_timeout_s;
    startJob(std::move(job), "look around", parameters_.explore_priority, o, d);
    return;
  }
  if (startTargetJob(o, d, false)) return;
  if (startTargetJob(o, d, true)) return;
  if (startExploreJob(o, d)) return;
  // No frontier left: what was given up and has moved since comes before
  // the rest of the ground to look at closely.
  if (reconsiderMoved(o, d) && startTargetJob(o, d, false)) return;
  if (startCloseLookJob(o, d)) return;
  // Nothing else left: the heard hypotheses not yet located too.
  if (parameters_.verify_located_first && startTargetJob(o, d, false, true)) return;

  if (!o.map) {
    if (o.t >= parameters_.confirm_timeout_s * 3)
      stop("no obstacle map has arrived: nothing can be explored", d);
    return;
  }
  int waiting = 0, no_viewpoint = 0, verified = 0, falsified = 0, given_up = 0;
  std::string unsettled;  // "; ID: why" for the first few left unsettled
  constexpr int kMostNamed = 10;
  for (const auto& h : o.hypotheses) {
    verified += h.verified ? 1 : 0;
    falsified += h.falsified ? 1 : 0;
    if (!wantsVerify(h) && !wantsInspect(h)) continue;
    const auto it = targets_.find(h.object_id);
    const bool left = it != targets_.end() && (it->second.given_up || it->second.no_viewpoint);
    if (left && given_up + no_viewpoint < kMostNamed) unsettled += "; " + h.object_id + ": " + it->second.why;
    if (it != targets_.end() && it->second.given_up) ++given_up;
    else if (it != targets_.end() && it->second.no_viewpoint) ++no_viewpoint;
    else ++waiting;
  }
  if (waiting > 0) return;  // a hypothesis is due for another try soon
  std::string reason = "nothing left to explore: " + std::to_string(o.hypotheses.size()) + " hypotheses (" +
                       std::to_string(verified) + " verified, " + std::to_string(falsified) + " falsified";
  if (given_up > 0) reason += ", " + std::to_string(given_up) + " given up";
  if (no_viewpoint > 0) reason += ", " + std::to_string(no_viewpoint) + " without a reachable viewpoint";
  reason += "), no reachable frontier left";
  if (parameters_.close_looks.enabled) reason += ", no reachable ground left to look at closely";
  reason += unsettled;
  if (parameters_.stop_when_done) {
    stop(reason, d);
    return;
  }
  if (reason != done_reason_) d.log.push_back(reason + "; watching until the scenario's end");
  done_reason_ = reason;
  idle_until_t_ = o.t + parameters_.idle_recheck_s;
}

bool Explorer::startTargetJob(const Observation& o, Decision& d, bool inspect, bool not_located_too) {
  const KnownMap* map = knownMap(o);
  if (map == nullptr) return false;
  // The hypotheses to try, each with the least score a viewpoint of it can
  // have: no viewpoint lies nearer the robot than the target less
  // max_distance, travel between cell centres is never shorter than the
  // straight line less a cell's diagonal, and penalties only add. Listed in
  // the hypotheses' order: the first of equal scores wins.
  struct Candidate {
    const HypothesisView* hypothesis;
    double gain;                          // what its DW weight is worth [m]
    SightMemory sights;                   // what its lines of sight showed when asked before
    std::optional<Viewpoint> viewpoint;   // its best, once found
  };
  std::vector<Candidate> candidates;
  std::vector<double> least_scores;
  for (const HypothesisView& h : o.hypotheses) {
    if (!(inspect ? wantsInspect(h) : wantsVerifyNow(h, not_located_too))) continue;
    TargetMemory& memory = targets_[h.object_id];
    tryAfreshIfMoved(h, memory, o, d);
    if (memory.given_up || o.t < memory.retry_t) continue;
    const double gain = parameters_.weight_gain_m * std::max(0.0, h.weight);
    const double least_travel = std::hypot(h.x - o.robot_x, h.y - o.robot_y) -
                                parameters_.viewpoints.max_distance_m - 1.5 * map->resolution();
    candidates.push_back({&h, gain, {}, std::nullopt});
    least_scores.push_back(std::max(0.0, least_travel) - gain);
  }
  if (candidates.empty()) return false;

  const TravelField travel(*map, o.robot_x, o.robot_y,
                           o.robot_radius + parameters_.safety_margin_m + map->resolution());
  // A hypothesis asked without a limit and without a viewpoint has none.
  const auto best_index = cheapestFirst(std::move(least_scores), [&](std::size_t i, double limit) -> std::optional<double> {
    Candidate& c = candidates[i];
    const HypothesisView& h = *c.hypothesis;
    TargetMemory& memory = targets_[h.object_id];
    c.viewpoint =
        chooseViewpoint(*map, travel, h.x, h.y, memory.tried, viewpointsFor(h), limit + c.gain, &c.sights);
    if (!c.viewpoint) {
      if (std::isinf(limit)) {
        if (!memory.no_viewpoint) d.log.push_back(h.object_id + ": no reachable viewpoint on the known map");
        memory.why = "no reachable viewpoint on the known map";
        memory.no_viewpoint = true;
        memory.retry_t = o.t + parameters_.retry_after_s;
      }
      return std::nullopt;
    }
    memory.no_viewpoint = false;
    return c.viewpoint->cost - c.gain;
  });
  if (!best_index) return false;
  const Viewpoint best_viewpoint = *candidates[*best_index].viewpoint;
  const HypothesisView* target = candidates[*best_index].hypothesis;
  Job job;
  job.kind = inspect ? JobKind::Inspect : JobKind::Verify;
  job.object_id = target->object_id;
  job.target = {target->x, target->y};
  job.x = best_viewpoint.x;
  job.y = best_viewpoint.y;
  job.yaw = best_viewpoint.yaw;
  job.sub_tasks.push_back(subTask("goto", job.x, job.y, job.yaw, "",
                                  "go to a viewpoint of " + target->object_id));
  job.sub_tasks.push_back(subTask("look_at", target->x, target->y, 0, target->object_id, "look at " + target->object_id));
  job.deadline_t = o.t + parameters_.attempt_timeout_s + best_viewpoint.travel_m / parameters_.nominal_speed;
  const std::string note = std::string(inspect ? "inspect " : "verify ") + target->object_id + " at " +
                           at(target->x, target->y) + " from " + at(job.x, job.y) + ", travel " +
                           fixed(best_viewpoint.travel_m) + " m";
  startJob(std::move(job), note, parameters_.verify_priority, o, d);
  return true;
}

bool Explorer::startExploreJob(const Observation& o, Decision& d) {
  const KnownMap* map = knownMap(o);
  if (map == nullptr) return false;
  const TravelField travel(*map, o.robot_x, o.robot_y, o.robot_radius + parameters_.safety_margin_m + map->resolution());
  const auto frontier = cheapestFrontier(*map, travel, memory_, {o.robot_x, o.robot_y});
  if (!frontier) return false;
  // Ground not looked at closely that the robot reaches sooner than the next
  // frontier is looked at now, while it is near: once the frontiers are
  // done, it may be far away.
  if (parameters_.close_looks.enabled) {
    const auto look = close_looks_.cheapestPatch(*map, travel, {o.robot_x, o.robot_y});
    if (look && look->travel_m < frontier->cost) {
      startCloseLook(*look, o, d);
      return true;
    }
  }
  const FrontierGoal& goal = *frontier;
  startJob(goingTo(JobKind::Explore, goal.x, goal.y, goal.yaw, goal.travel_m, "go to the frontier", o),
           "explore the frontier at " + at(goal.x, goal.y) + " (" + std::to_string(goal.size) + " cells, travel " +
               fixed(goal.travel_m) + " m)",
           parameters_.explore_priority, o, d);
  return true;
}

Explorer::Job Explorer::goingTo(JobKind kind, double x, double y, double yaw, double travel_m,
                               const std::string& note, const Observation& o) const {
  Job job;
  job.kind = kind;
  job.x = x;
  job.y = y;
  job.yaw = yaw;
  job.sub_tasks.push_back(subTask("goto", x, y, yaw, "", note));
  job.deadline_t = o.t + parameters_.attempt_timeout_s + travel_m / parameters_.nominal_speed;
  return job;
}

bool Explorer::startCloseLookJob(const Observation& o, Decision& d) {
  if (!parameters_.close_looks.enabled) return false;
  const KnownMap* map = knownMap(o);
  if (map == nullptr) return false;
  const TravelField travel(*map, o.robot_x, o.robot_y, o.robot_radius + parameters_.safety_margin_m + map->resolution());
  const auto look = close_looks_.cheapestPatch(*map, travel, {o.robot_x, o.robot_y});
  if (look) startCloseLook(*look, o, d);
  return look.has_value();
}

void Explorer::startCloseLook(const CloseLookGoal& goal, const Observation& o, Decision& d) {
  Job job = goingTo(JobKind::CloseLook, goal.x, goal.y, goal.yaw, goal.travel_m, "go to look closely at the ground", o);
  for (const double yaw : goal.turns)
    job.sub_tasks.push_back(subTask("turn", 0, 0, yaw, "", "look closely at the ground around"));
  const double cell_m = parameters_.close_looks.cell_m;
  startJob(std::move(job),
           "look closely at the ground from " + at(goal.x, goal.y) + " (" + fixed(goal.size * cell_m * cell_m) +
               " m2 not looked at closely, travel " + fixed(goal.travel_m) + " m)",
           parameters_.explore_priority, o, d);
}

void Explorer::closeLookVisited(const Observation& o, const Job& job) {
  if (const KnownMap* map = knownMap(o)) close_looks_.visited(*map, {job.x, job.y});
}

}  // namespace beft::exploration

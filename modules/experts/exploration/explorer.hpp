// The exploration expert's logic (section "Active exploration"), one decision
// per tick, without LCM.
//
// What it does, in order of preference:
//  1. At the start, look around: turn the platform in place a full circle
//     (a composite `explore` task with four `turn` sub-tasks).
//  2. Verify: a hypothesis heard but not settled (neither verified nor
//     falsified by vision) gets a viewpoint (viewpoints.hpp); a composite
//     `verify` task with sub-tasks `goto x y yaw` (facing the target) then
//     `look_at object` is pushed. When fusion settles the hypothesis the task
//     is finished; when the robot got there, looked, and it is still unsettled,
//     the attempt failed: another viewpoint is tried (tried ones are
//     remembered), up to max_attempts, then the hypothesis is given up.
//  3. Inspect: a hypothesis glimpsed (some pixels, too few to count as seen),
//     never heard, that may be a person, is approached the same way.
//  4. Explore: the nearest reachable frontier (frontiers.hpp), facing the
//     unknown, or look closely, when it is nearer, at a patch of the known
//     free ground the camera has not yet had in view up close
//     (close_looks.hpp): depth maps a floor from farther away than vision
//     sees who lies on it. Once no frontier is left, a hypothesis given up
//     that has moved far since is tried again first, then the rest of the
//     ground is looked at. A hypothesis to verify interrupts either; a
//     glimpsed possible person, a close look.
//  5. Stop: nothing to verify or inspect, no reachable frontier and no
//     ground left to look at closely, or the scenario's duration reached: a
//     stop request with the reason. With stop_when_done off, it keeps
//     watching instead (a new sound to verify starts it again) and asks to
//     stop only when the duration is reached.
//
// Hypotheses are chosen by DW weight (the sounds that matter first), then by
// the cost of their best viewpoint. Only what the robot perceived is used:
// hypotheses, the obstacle map, its own state and the task stack.
// Deterministic: decisions depend only on the inputs and their order.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "experts/exploration/close_looks.hpp"
#include "experts/exploration/frontiers.hpp"
#include "experts/exploration/known_map.hpp"
#include "experts/exploration/viewpoints.hpp"

namespace beft::exploration {

// A hypothesis as fusion publishes it, with what the choice needs.
struct HypothesisView {
  std::string object_id;
  double x = 0, y = 0;               // estimated position [m]
  bool seen = false, heard = false, verified = false, falsified = false;
  bool glimpsed = false;             // perceived by vision without counting as seen
  std::string best_category;
  double confidence = 0;             // of best_category
  double person_confidence = 0;      // fused confidence of `person`
  double weight = -1;                // DW weight, -1 when DW has none
  bool located = true;               // false: a point along a heard bearing at an assumed range
};

// One task of the stack (top first), as task_t carries it.
struct StackEntry {
  int64_t id = 0, parent = 0;
  std::string kind, object_id, origin;
  int8_t status = 0;  // task_t::STATUS_*
};

struct Observation {
  double t = 0;                      // simulated time [s]
  double duration = 0;               // scenario duration [s], <= 0 unknown
  double robot_x = 0, robot_y = 0, robot_yaw = 0;  // [m], [deg]
  double head_yaw = 0;               // head pan relative to the platform [deg]
  double robot_radius = 0.35;        // [m]
  bool robot_known = false;
  std::vector<HypothesisView> hypotheses;
  std::shared_ptr<const planners::ObstacleCells> map;  // null until one arrived
  int64_t map_version = 0;           // changes when the map does
  std::vector<StackEntry> stack;     // top first
  bool stack_known = false;          // a TASK_STACK has arrived
};

// A change to the task stack, for TASK_COMMAND.
struct TaskRequest {
  enum class Type { Push, Finish } type = Type::Push;
  // Push:
  int64_t parent = 0;
  std::string kind, object_id, note;
  int32_t priority = 0;
  double x = 0, y = 0, yaw = 0;
  // Finish:
  int64_t task_id = 0;
  bool success = true;
  std::string reason;
};

struct Decision {
  std::vector<TaskRequest> requests;
  std::optional<std::string> stop;   // the run should end, and why
  std::vector<std::string> log;      // what was decided, for the process log
};

struct ExplorerParameters {
  std::string origin = "exploration";  // name on the tasks it pushes
  int32_t verify_priority = 20;
  int32_t explore_priority = 10;
  double safety_margin_m = 0.15;       // added to the robot radius for standable cells
  bool look_around = true;             // turn a full circle at the start
  int verify_attempts = 4;             // viewpoints per heard hypothesis before giving up
  // A heard hypothesis whose estimate lay in plain view after a look (in
  // the camera's view, within the viewpoints' max_distance_m, every map cell
  // of the sight line known and free) and still did not settle is given up
  // at once: nothing is where it was heard, and other viewpoints of that
  // empty place would not change it (a heard estimate that crossed the wrong
  // bearings). It is tried again once placed moved_m away. Only a located
  // estimate counts: one not yet triangulated lies at an assumed range along
  // its bearing, a place that is empty although the source is farther on.
  bool give_up_in_plain_view = true;
  // A heard hypothesis not yet located (its estimate only a point at an
  // assumed range along its bearing) is verified once no frontier and no
  // ground to look at closely is left, not at once: looking at that point
  // finds nothing where the source is farther on, and the robot's own
  // travel meanwhile crosses its bearings. In generated districts heard
  // binaurally, most of the first 400 s went to such looks, four per
  // source. A located one is verified at once, as before.
  bool verify_located_first = true;
  int inspect_attempts = 2;            // viewpoints per glimpsed hypothesis
  int ruled_out_viewpoints = 12;       // viewpoints the map rules out on the way before a first look (no attempt)
  // Of those, viewpoints ruled out while a frontier lies within the
  // viewpoints' max_distance_m of the target (the walls around it still
  // being mapped, its open side perhaps not yet seen) do not count, up to
  // this many in all.
  int ruled_out_while_mapping = 36;
  // A hypothesis now placed at least this far [m] from where its viewpoints
  // were tried, beyond how far the robot moved meanwhile, is tried afresh:
  // a heard estimate that jumped (its bearings crossed at last, or it had
  // been placed where another source of the same sound is) makes the
  // viewpoints tried for the old place no failure at the new one. An
  // estimate still only on its bearing lies a few metres from the robot
  // and moves with it: that is no jump. One given up is tried again once
  // no frontier is left (before the ground still to look at closely), if
  // placed this far from where it was when given up. At most
  // tries_after_moving times in all (0 m: never).
  double moved_m = 8.0;
  int tries_after_moving = 3;
  bool inspect_glimpsed = true;
  double inspect_person_margin = 0.0; // glimpsed: person within this of the best category
  double look_dwell_s = 1.5;           // after looking, wait this long for fusion to settle
  double confirm_timeout_s = 3.0;      // a pushed task must show on the stack within this
  double attempt_timeout_s = 30.0;     // plus travel / speed
  double nominal_speed = 0.5;          // [m/s] to scale the timeout
  double retry_after_s = 5.0;          // a hypothesis without a viewpoint is reconsidered after this
  double revalidate_period_s = 0.5;    // how often a running task's goal is re-checked
  double weight_gain_m = 20.0;         // a DW weight of 1 is worth this much travel
  double stood_spacing_m = 0.5;        // the robot's trail is sampled at this pitch
  double frontier_check_radius_m = 1.0;  // an explore goal ends when no frontier is this near it
  bool stop_when_done = true;          // request the stop when nothing is left (else at the duration)
  double idle_recheck_s = 2.0;         // when done and watching, look for work again this often
  // Half a car's diagonal and a margin [m]: its occupied cells this close are
  // its own body, not obstacles in front of it (target_cells.hpp).
  double car_extent_m = 2.8;
  // A fire's: its 0.5 m radius and a margin [m]. Its outermost cells lie
  // beyond target_clearance_m and would block the sight lines to its sides
  // from everywhere, its own best viewpoint too.
  double fire_extent_m = 1.0;
  ViewpointParameters viewpoints;
  FrontierParameters frontiers;
  CloseLookParameters close_looks;
};

class Explorer {
 public:
  explicit Explorer(ExplorerParameters parameters = {});

  Decision step(const Observation& observation);
  // Whether the next step at sim time t will look at the map: decoding a map
  // message can be skipped when not (a running task between its checks).
  bool wantsMap(double t) const;

  // For tests and logs.
  enum class Phase { LookAround, Verify, Explore, Idle, Stopped };
  Phase phase() const;
  bool stopped() const { return stopped_; }
  int attempts(const std::string& object_id) const;
  bool givenUp(const std::string& object_id) const;
  const std::vector<Point>& triedViewpoints(const std::string& object_id) const;
  const CloseLookCoverage& closeLooks() const { return close_looks_; }

 private:
  enum class JobKind { LookAround, Verify, Inspect, Explore, CloseLook };
  struct Job {
    JobKind kind = JobKind::Explore;
    std::string object_id;           // verify / inspect
    double x = 0, y = 0, yaw = 0;    // goal pose
    Point target;                    // verify / inspect: where the hypothesis was placed when the job began
    std::vector<TaskRequest> sub_tasks;  // pushed once the composite shows; they run in this order
    int64_t composite_id = 0;        // 0 until seen on the stack
    double sub_tasks_pushed_t = -1;  // when the sub-tasks were pushed, -1 not yet
    double pushed_t = 0;
    double done_looking_t = -1;      // when the sub-tasks had all ended
    double deadline_t = 0;
    double last_check_t = 0;
  };
  struct TargetMemory {
    int attempts = 0;                // viewpoints tried: reached, looked from, still unsettled
    int ruled_out = 0;               // viewpoints the map ruled out before the robot got there
    int ruled_out_while_mapping = 0; // of those, not counted: its surroundings were still being mapped
    std::vector<Point> tried;
    std::optional<Point> tried_at;   // where the hypothesis was placed when its first viewpoint failed or was ruled out
    Point robot_at_try;              // where the robot was then
    bool given_up = false;
    std::optional<Point> given_up_at;  // where the hypothesis was placed when it was given up
    int tries_after_moving = 0;        // times it was tried again after it moved
    bool no_viewpoint = false;       // the last search found no viewpoint
    double retry_t = -1;             // not reconsidered before this sim time
    std::string why;                 // why it is not settled yet, as the log said last
  };

  void updateTrail(const Observation& o);
  // Targets given up that are now placed far from where they were: tried
  // again. True if there was one.
  bool reconsiderMoved(const Observation& o, Decision& d);
  // A target not given up that is now placed far from where its viewpoints
  // were tried, with a try after moving left: tried afresh (its attempts
  // were at another place).
  bool placedFarFromItsTries(const HypothesisView& h, const TargetMemory& memory, const Observation& o) const;
  void tryAfreshIfMoved(const HypothesisView& h, TargetMemory& memory, const Observation& o, Decision& d);
  // Where the hypothesis moved since its viewpoints were tried, less how far
  // the robot moved meanwhile [m].
  static double movedMoreThanTheRobot(const HypothesisView& h, const TargetMemory& memory, const Observation& o);
  // Notes where the target and the robot were at its first failed or ruled-out viewpoint.
  void noteFirstTry(TargetMemory& memory) const;
  // Marks the target given up, where the job that tried it last placed it.
  void giveUp(TargetMemory& memory);
  bool wantsVerify(const HypothesisView& h) const;
  // wantsVerify, and located unless not_located_too (verify_located_first).
  bool wantsVerifyNow(const HypothesisView& h, bool not_located_too) const;
  bool wantsInspect(const HypothesisView& h) const;
  // A hypothesis to verify or inspect that has not been tried in vain yet.
  bool hasFreshTarget(const Observation& o) const;
  const HypothesisView* findHypothesis(const Observation& o, const std::string& id) const;
  // The viewpoint parameters for one target: a car's body reaches
  // car_extent_m, a fire's fire_extent_m.
  ViewpointParameters viewpointsFor(const HypothesisView& h) const;

  void followJob(const Observation& o, Decision& d);
  void awaitCompositeId(const Observation& o, Decision& d);
  bool endIfSettledOrGone(const Observation& o, Decision& d, bool on_stack);
  bool endIfInterrupted(const Observation& o, Decision& d);
  bool endIfLookedOrLate(const Observation& o, Decision& d, int sub_tasks);
  void revalidate(const Observation& o, Decision& d);
  void endJob(const Observation& o, Decision& d, bool success, const std::string& reason, bool finish_on_stack);
  void recordFailedAttempt(const std::string& object_id, const Point& viewpoint, const std::string& why, Decision& d);
  // The hypothesis' estimate, if it is in plain view of the camera now (give_up_in_plain_view).
  std::optional<Point> estimateInPlainView(const Observation& o, const std::string& object_id);
  void recordRuledOut(const std::string& object_id, const Point& viewpoint, const std::string& why,
                      bool while_mapping, Decision& d);
  // Whether a frontier lies within the viewpoints' reach of a target.
  bool surroundingsBeingMapped(const Observation& o, const std::string& object_id);
  void finishStrayComposites(const Observation& o, Decision& d);
  bool jobStillValid(const Observation& o, std::string& why);

  void decide(const Observation& o, Decision& d);
  // Verifies a heard hypothesis (wantsVerifyNow), or with inspect inspects a
  // glimpsed one: the cheapest to reach first.
  bool startTargetJob(const Observation& o, Decision& d, bool inspect, bool not_located_too = false);
  // The cheapest frontier, or the patch of ground not looked at closely
  // that the robot reaches soonest when it is nearer; false with no frontier.
  bool startExploreJob(const Observation& o, Decision& d);
  // With no frontier left: the patch the robot reaches soonest.
  bool startCloseLookJob(const Observation& o, Decision& d);
  void startCloseLook(const CloseLookGoal& goal, const Observation& o, Decision& d);
  // A job whose first sub-task is a goto to (x, y, yaw), due after the
  // attempt timeout plus the travel at nominal speed.
  Job goingTo(JobKind kind, double x, double y, double yaw, double travel_m, const std::string& note,
              const Observation& o) const;
  // Marks the ground the camera looks at closely now.
  void lookClosely(const Observation& o);
  // What could not be looked at closely from the job's goal is not asked for again.
  void closeLookVisited(const Observation& o, const Job& job);
  void startJob(Job job, const std::string& note, int32_t priority, const Observation& o, Decision& d);
  void stop(const std::string& reason, Decision& d);

  // Map views, rebuilt when the map or the robot's radius changes.
  const KnownMap* knownMap(const Observation& o);

  ExplorerParameters parameters_;
  std::optional<Job> job_;
  std::map<std::string, TargetMemory> targets_;
  ExplorationMemory memory_;         // where the robot stood, frontier goals visited
  CloseLookCoverage close_looks_;    // the ground looked at closely
  std::vector<int64_t> known_task_ids_;  // composites of ours already matched to a job
  std::vector<int64_t> finish_sent_;     // composites we asked the stack to finish
  bool looked_around_ = false;
  bool stopped_ = false;
  std::string stop_reason_;
  std::string done_reason_;          // why there is nothing left, while watching
  double idle_until_t_ = -1;         // watching: next look for work
  std::unique_ptr<KnownMap> map_;
  int64_t map_version_ = -1;
  double map_radius_ = -1;
};

}  // namespace beft::exploration

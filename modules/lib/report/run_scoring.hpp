// Scoring a run against ground truth: which persons were found, where, how
// sure and when; which hypotheses were falsified; what was missed.
//
// A victim is found when a hypothesis, at the end of the run, has `person` as
// its best fused category with a confidence of at least person_confidence,
// was seen by vision and is not falsified. Being heard is not enough: a radio
// playing a voice sounds like a person until the camera shows it (decoy.xml).
// The hypothesis is matched to the ground-truth person it names (fusion keys
// hypotheses by object id); failing that, to the nearest person not yet
// matched within match_radius. A found hypothesis that matches no person is a
// false alarm; two hypotheses for the same person keep the more confident one.
#pragma once

#include <optional>
#include <map>
#include <string>
#include <vector>

#include "lib/report/run_record.hpp"
#include "lib/scenario/scenario.hpp"

namespace beft::report {

struct ScoringOptions {
  double person_confidence = 0.6;   // minimum fused confidence of `person` [0..1]
  double match_radius = 2.0;        // spatial match when ids differ [m]
  std::string person_label = "person";
  std::optional<double> wall_time_s;  // as measured by the runner; else from log timestamps
  bool log_incomplete = false;         // the runner says the recorder died during the run
};

struct VictimEntry {
  std::string object;       // ground-truth person id
  std::string hypothesis;   // the hypothesis' object id
  double x = 0, y = 0;      // estimated position [m]
  // The person's true position when the hypothesis last placed it (its last
  // position update; GT_OBJECTS of that tick), so a walker located when seen
  // is not charged for walking on afterwards. Without that tick in the log:
  // the true position at the end of the run.
  double true_x = 0, true_y = 0;  // [m]
  double error_m = 0;       // distance from (x, y) to (true_x, true_y) [m]
  double placed_at_s = -1;  // sim time of that position update, -1 if unknown
  double confidence = 0;    // fused confidence of `person`
  bool verified = false;
  double found_at_s = 0;    // first sim time the hypothesis met the victim test
  // Path efficiency (SPL per victim), when the ground truth allowed it
  // (beft-report with the scenario): the shortest path from the robot's start
  // to a viewpoint of the person, the distance driven until it was found, and
  // shortest / max(shortest, driven).
  std::optional<double> shortest_path_m, driven_m, path_efficiency;
};

// Where the audio expert last put a sounding object, and how far off it was.
struct HeardEntry {
  std::string object;
  double x = 0, y = 0;            // estimate [m]
  double true_x = 0, true_y = 0;  // [m]
  double error_m = 0;
  double at_s = 0;                // sim time of the estimate [s]
};

struct FalsifiedEntry {
  std::string object;       // hypothesis object id
  double x = 0, y = 0;      // estimated position [m]
  std::string heard_as, seen_as;
  double settled_at_s = -1;
};

struct FalseAlarm {
  std::string hypothesis;
  double x = 0, y = 0;
  double confidence = 0;
  std::string reason;
};

struct RunReport {
  std::string scenario;
  std::string log_path;
  bool completed = false;       // every person found and every hypothesis settled
  double sim_time_s = 0;
  double wall_time_s = 0;           // the whole run, start and stop of every process included
  bool wall_time_measured = false;  // from --wall-time rather than log timestamps
  double ticking_time_s = 0;        // the lockstep loop: first FIRE to last DONE (log times)
  int64_t ticks = 0;
  double ticks_per_s = 0;       // ticks / ticking time (wall time if that is unknown); 0 if neither is
  double realtime_factor = 0;   // sim time / ticking time (or wall time)
  double overall_realtime_factor = 0;  // sim time / wall time
  double path_length_m = 0;
  int collisions = 0;
  int persons = 0;              // ground-truth persons
  std::vector<VictimEntry> victims;
  std::vector<FalsifiedEntry> falsified;
  std::vector<HeardEntry> heard;        // every object the audio expert reported, by id
  std::vector<std::string> missed;      // ground-truth persons not found
  // The mean of the victims' path_efficiency over every person present, 0
  // for a person missed (SPL); unset when it was not computed.
  std::optional<double> path_efficiency_mean;
  std::vector<FalseAlarm> false_alarms;
  std::vector<std::string> unsettled;   // heard, neither verified nor falsified
  std::map<std::string, std::string> unsettled_why;  // per unsettled hypothesis, when known: why
  int hypotheses = 0;
  std::string end_reason;
  std::map<std::string, int64_t> rejected_messages;  // per channel: malformed or of another type
  std::string log_damage;                             // "" when the log was whole
  bool log_complete = true;                           // false when the recorder died during the run, or its
                                                      // final RECORD_STATUS says a message is missing
  int64_t log_messages_lost = 0;                      // messages the recorder knows were sent and never got
  int64_t log_messages_repaired = 0;                  // messages it got only by asking again (loss repair)
  int64_t other_run_messages = 0;                     // another run's messages heard on the URL, left out
  std::map<std::string, int64_t> unauthenticated_messages;  // per process: refused in a keyed run, no valid tag
  double person_confidence = 0;
};

// Fills what the log lacks (no GT_OBJECTS: objects, world size, dt, duration,
// name) from the scenario file. Returns warnings, e.g. a name mismatch.
std::vector<std::string> applyScenario(RunRecord& record, const scenario::Scenario& scenario);

RunReport scoreRun(const RunRecord& record, const ScoringOptions& options);

// What the processes of a keyed run refused for want of a valid tag, all
// together (a message refused by three processes counts three times).
int64_t unauthenticatedTotal(const RunReport& report);

// A hypothesis counts as settled when vision verified or falsified it, or when
// it was never heard (nothing to verify).
bool isSettled(const HypothesisState& hypothesis);

}  // namespace beft::report

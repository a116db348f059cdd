#include "lib/report/run_scoring.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace beft::report {
namespace {

TruthObject toTruth(const scenario::Object& object) {
  TruthObject truth;
  truth.id = object.id;
  truth.label = object.label;
  truth.x = object.x;
  truth.y = object.y;
  truth.yaw = object.yaw;
  truth.acoustic = object.acoustic.has_value();
  if (object.visual) {
    if (object.visual->shape == scenario::Visual::Shape::Box) {
      truth.shape = TruthObject::Shape::Box;
      truth.size_x = object.visual->size_x;
      truth.size_y = object.visual->size_y;
    } else {
      truth.shape = TruthObject::Shape::Cylinder;
      truth.radius = object.visual->radius;
      truth.size_x = truth.size_y = 2 * object.visual->radius;
    }
  }
  return truth;
}

bool isVictimCandidate(const HypothesisState& h, const ScoringOptions& options) {
  return h.best_category == options.person_label && h.confidence >= options.person_confidence && h.seen &&
         !h.falsified;
}

// First sim time each hypothesis met the victim test, if it ever did.
std::map<std::string, double> firstFoundTimes(const RunRecord& record, const ScoringOptions& options) {
  std::map<std::string, double> found;
  for (const auto& sample : record.hypotheses)
    for (const auto& h : sample.hypotheses)
      if (isVictimCandidate(h, options)) found.emplace(h.object_id, sample.t);
  return found;
}

}  // namespace

bool isSettled(const HypothesisState& hypothesis) {
  return hypothesis.verified || hypothesis.falsified || !hypothesis.heard;
}

int64_t unauthenticatedTotal(const RunReport& report) {
  int64_t total = 0;
  for (const auto& entry : report.unauthenticated_messages) total += entry.second;
  return total;
}

std::vector<std::string> applyScenario(RunRecord& record, const scenario::Scenario& scenario) {
  std::vector<std::string> warnings;
  if (!record.scenario_name.empty() && record.scenario_name != scenario.name)
    warnings.push_back("the log is of scenario '" + record.scenario_name + "' but " + scenario.file +
                       " is '" + scenario.name + "'");
  if (record.scenario_name.empty()) record.scenario_name = scenario.name;
  if (record.world_width <= 0 || record.world_height <= 0) {
    record.world_width = scenario.world.width;
    record.world_height = scenario.world.height;
  }
  if (record.dt <= 0) record.dt = scenario.dt;
  if (record.duration <= 0) record.duration = scenario.duration;
  if (record.categories.empty()) record.categories = scenario.categories;
  if (record.robot_radius <= 0) record.robot_radius = scenario.robot.radius;
  if (record.truth.empty()) {
    warnings.push_back("the log has no GT_OBJECTS: scoring against the scenario's initial positions");
    for (const auto& object : scenario.objects) record.truth.push_back(toTruth(object));
  }
  return warnings;
}

namespace {

// Speed, distance and how the run ended.
void scoreRunFigures(const RunRecord& record, const ScoringOptions& options, RunReport& report) {
  report.scenario = record.scenario_name;
  report.log_path = record.log_path;
  report.person_confidence = options.person_confidence;
  report.sim_time_s = record.simTime();
  report.ticks = record.tickCount();
  report.wall_time_measured = options.wall_time_s.has_value();
  report.wall_time_s = options.wall_time_s ? *options.wall_time_s : record.wallSpan();
  report.ticking_time_s = record.tickingSpan();
  const double loop_s = report.ticking_time_s > 0 ? report.ticking_time_s : report.wall_time_s;
  if (loop_s > 0) {
    report.ticks_per_s = report.ticks / loop_s;
    report.realtime_factor = report.sim_time_s / loop_s;
  }
  if (report.wall_time_s > 0) report.overall_realtime_factor = report.sim_time_s / report.wall_time_s;
  if (!record.robot.empty()) {
    report.path_length_m = record.robot.back().path_length;
    report.collisions = record.robot.back().collisions;
  }
  report.end_reason = !record.stop_reason.empty() ? record.stop_reason : record.run_status;
  report.rejected_messages = record.rejected;
  report.log_damage = record.log_damage;
  // Complete: the recorder lived through the run, and its final account says
  // it holds every message its senders announced (logs older than that
  // account are taken as complete unless the runner said otherwise).
  report.log_complete = !options.log_incomplete;
  report.other_run_messages = record.other_run_messages;
  if (record.record_status) {
    const auto& status = *record.record_status;
    report.log_complete = report.log_complete && status.final && status.complete;
    report.log_messages_lost = status.lost;
    report.log_messages_repaired = status.repaired;
    report.other_run_messages = std::max(report.other_run_messages, status.other_run_messages);
  }
  for (const auto& [process, refused] : record.process_rejects)
    if (refused.unauthenticated > 0) report.unauthenticated_messages[process] = refused.unauthenticated;
}

// The person a victim candidate stands for: the one of its id, else the
// nearest person not yet matched within the match radius; null if none.
const TruthObject* personOf(const HypothesisState& h, const std::vector<const TruthObject*>& persons,
                            const std::set<std::string>& matched, const ScoringOptions& options) {
  for (const auto* p : persons)
    if (p->id == h.object_id) return p;
  const TruthObject* person = nullptr;
  double best = options.match_radius;
  for (const auto* p : persons) {
    const double d = std::hypot(p->x - h.x, p->y - h.y);
    if (matched.count(p->id) == 0 && d <= best) {
      best = d;
      person = p;
    }
  }
  return person;
}

// Victims in ground-truth order, for a stable report; the others missed.
void orderVictims(const std::vector<const TruthObject*>& persons, RunReport& report) {
  std::vector<VictimEntry> ordered;
  for (const auto* p : persons) {
    bool found = false;
    for (const auto& v : report.victims)
      if (v.object == p->id) {
        ordered.push_back(v);
        found = true;
      }
    if (!found) report.missed.push_back(p->id);
  }
  report.victims.swap(ordered);
}

// The estimate against where the person was when the hypothesis last placed
// it: a moving person's error is not the distance it walked since.
void placeVictim(const RunRecord& record, const HypothesisState& h, const TruthObject& person,
                 VictimEntry& victim) {
  victim.x = h.x;
  victim.y = h.y;
  victim.true_x = person.x;
  victim.true_y = person.y;
  if (const auto then = record.truthAt(person.id, h.placed_tick); then && h.placed_tick >= 0) {
    victim.true_x = then->x;
    victim.true_y = then->y;
    victim.placed_at_s = h.placed_s;
  }
  victim.error_m = std::hypot(victim.true_x - h.x, victim.true_y - h.y);
}

}  // namespace

RunReport scoreRun(const RunRecord& record, const ScoringOptions& options) {
  RunReport report;
  scoreRunFigures(record, options, report);
  std::vector<const TruthObject*> persons;
  for (const auto& object : record.truth)
    if (object.label == options.person_label) persons.push_back(&object);
  report.persons = static_cast<int>(persons.size());

  const std::vector<HypothesisState> none;
  const auto& final_hypotheses = record.hypotheses.empty() ? none : record.hypotheses.back().hypotheses;
  report.hypotheses = static_cast<int>(final_hypotheses.size());
  const auto found_times = firstFoundTimes(record, options);

  // Candidates in decreasing confidence, so a duplicate loses to the surer one.
  std::vector<const HypothesisState*> candidates;
  for (const auto& h : final_hypotheses) {
    if (h.falsified) report.falsified.push_back({h.object_id, h.x, h.y, h.heard_as, h.seen_as, h.settled_s});
    if (!isSettled(h)) report.unsettled.push_back(h.object_id);
    if (isVictimCandidate(h, options)) candidates.push_back(&h);
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const HypothesisState* a, const HypothesisState* b) { return a->confidence > b->confidence; });

  std::set<std::string> matched;
  for (const auto* h : candidates) {
    const TruthObject* person = personOf(*h, persons, matched, options);
    if (person == nullptr) {
      report.false_alarms.push_back({h->object_id, h->x, h->y, h->confidence, "matches no person"});
      continue;
    }
    if (matched.count(person->id) > 0) {
      report.false_alarms.push_back({h->object_id, h->x, h->y, h->confidence, "duplicate of " + person->id});
      continue;
    }
    matched.insert(person->id);
    VictimEntry victim;
    victim.object = person->id;
    victim.hypothesis = h->object_id;
    placeVictim(record, *h, *person, victim);
    victim.confidence = h->confidence;
    victim.verified = h->verified;
    const auto found = found_times.find(h->object_id);
    victim.found_at_s = found != found_times.end() ? found->second : report.sim_time_s;
    report.victims.push_back(victim);
  }
  orderVictims(persons, report);
  report.completed = report.missed.empty() && report.unsettled.empty();
  for (const auto& [object, heard] : record.heard)
    report.heard.push_back({object, heard.x, heard.y, heard.true_x, heard.true_y,
                            std::hypot(heard.x - heard.true_x, heard.y - heard.true_y), heard.t});
  return report;
}

}  // namespace beft::report

// Dynamic weighting of acoustic objects (paper section 3, eq. 4; spec/model.md
// "Dynamic weighting, eq. 4"): one weight per object heard, stepped at a fixed
// interval of simulated time, and the turn-to reflex when a weight crosses the
// reflex threshold upward. Plain logic, no LCM.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lib/model/model.hpp"

namespace beft::dw {

// c for (label, activity) pairs. Starts with the scenario format's default
// table; a scenario's table replaces it. Pairs not in the table give the
// default value.
class CongruencyTable {
 public:
  CongruencyTable();  // the default pairs of spec/scenario-format.md
  void clear() { values_.clear(); }
  void set(const std::string& label, const std::string& activity, double c);
  double of(const std::string& label, const std::string& activity) const;
  void setDefaultValue(double c) { default_value_ = c; }
  std::size_t size() const { return values_.size(); }

 private:
  std::map<std::pair<std::string, std::string>, double> values_;
  double default_value_ = 0.5;
};

struct DwParameters {
  int t_max = 10;                 // T_max of eq. 4 [DW steps]
  double n = 100;                 // n of eq. 4
  double initial_weight = 0.5;    // weight of a newly heard object
  double incongruent_c = 0.75;    // a pair with c >= this rises, others fall
  double reflex_threshold = 0.75; // upward crossing triggers the turn-to reflex
  bool reevaluate = true;         // re-evaluate c after T_max unchanged steps
  double residual_floor = 0.5;    // the lowest weight of an object that has been incongruent
  // Danger between objects: a person within danger_radius (centre to centre)
  // of a hazard (a label of danger_labels whose current pair has c >=
  // incongruent_c) is endangered: its c is incongruent_c. 0 turns it off.
  double danger_radius = 3.0;     // [m]
  std::vector<std::string> danger_labels{"fire"};
  std::string endangered_label = "person";
};

// One object sounding at a DW step, as the acoustic experts estimate it.
struct Stimulus {
  std::string object_id;
  std::string label;     // estimated acoustic label
  std::string activity;  // activity of the source
  double x = 0, y = 0;   // estimated position, world frame [m]
};

// The state machine of one acoustic object.
struct ObjectWeight {
  std::string object_id;
  double weight = 0.5;      // w in [0, 1]
  double congruency = 0.5;  // c of the current curve
  bool rising = false;      // direction of the current curve
  int step = 0;             // t: DW steps on the current curve (0 = not on one yet)
  int unchanged_steps = 0;  // consecutive DW steps in which w did not change
  std::string label, activity;  // the last pair heard
  double x = 0, y = 0;          // the last position estimate [m]
  bool sounding = false;        // sounding at the last DW step
  int64_t first_step = 0;       // DW step index when first heard
  bool was_incongruent = false; // once incongruent, residual_floor is its floor
  bool endangered = false;      // near a hazard at the last DW step
};

// An upward crossing of the reflex threshold at one DW step.
struct ReflexTrigger {
  std::string object_id;
  double weight_before = 0, weight_after = 0;
  double x = 0, y = 0;  // where the object was estimated [m]
};

class DynamicWeighting {
 public:
  explicit DynamicWeighting(DwParameters parameters = {}, CongruencyTable table = {});

  void setTable(CongruencyTable table) { table_ = std::move(table); }
  const CongruencyTable& table() const { return table_; }
  const DwParameters& parameters() const { return parameters_; }

  // One DW step with every object that sounds now. An object not listed has
  // fallen silent: one that was never incongruent keeps its weight; an
  // incongruent one falls to the residual (spec/model.md). Returns the reflex
  // triggers of this step, in the order the objects were first heard.
  std::vector<ReflexTrigger> step(const std::vector<Stimulus>& sounding);

  // Every object ever heard, in the order first heard.
  const std::vector<ObjectWeight>& objects() const { return objects_; }
  const ObjectWeight* find(const std::string& object_id) const;
  int64_t stepsTaken() const { return steps_taken_; }

 private:
  // Advances one known object by one step: heard with congruency c, or
  // silent (nullopt); returns its new weight.
  double advance(ObjectWeight& object, std::optional<double> c) const;
  double curve(const ObjectWeight& object) const;
  void startCurve(ObjectWeight& object, double c) const;
  // Marks every person near a hazard, from the last pair and position heard.
  void markEndangered();

  DwParameters parameters_;
  model::Parameters curve_parameters_;
  CongruencyTable table_;
  std::vector<ObjectWeight> objects_;
  int64_t steps_taken_ = 0;
};

// Step index of a simulated time for a step interval: floor(utime / step_us).
// DW steps once per new index, so steps land at t = 0, step, 2 step, ...
int64_t stepIndex(int64_t utime, int64_t step_us);

}  // namespace beft::dw

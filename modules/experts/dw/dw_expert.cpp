#include "experts/dw/dw_expert.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include <beft/dynamic_weights_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/common/log.hpp"
#include "lib/model/model.hpp"
#include "lib/task/task.hpp"
#include "lib/task/task_commands.hpp"
#include "lib/task/task_messages.hpp"

namespace beft::dw {

namespace {
std::string fmt(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.2f", value);
  return buffer;
}
}  // namespace

std::string DwExpert::description() const {
  return "High-level dynamic-weighting expert (paper section 3, eq. 4): keeps a weight in [0, 1] "
         "for every acoustic object heard (0 congruent, 1 incongruent or dangerous), stepped every "
         "dw_step_s of simulated time. A new object starts at 0.5; its congruency c comes from its "
         "estimated label (best category of LABELS_ACOUSTIC) and activity (AUDIO) through the "
         "scenario's congruency table (GT_OBJECTS). The weight rises while c >= 0.75 and falls "
         "otherwise; only a change to an incongruent c jumps (to 0.75); once incongruent, an object "
         "falls back to residual_floor and no lower, heard or silent; a silent object that never was "
         "incongruent keeps its weight; a person within danger_radius of a spreading fire is "
         "endangered (c = 0.75). Turn-to "
         "reflex: when a weight crosses reflex_threshold upward, a look_at task for that object is "
         "pushed on TASK_COMMAND with priority reflex_priority. Publishes DYNAMIC_WEIGHTS every tick "
         "(every weight, the viewing direction it computes: towards the object with the highest weight "
         "at or above reflex_threshold, NaN when none; the current task from TASK_STACK).";
}

void DwExpert::declareParameters(DeclaredParameters& parameters) {
  parameters.declare("dw_step_s", step_s_, 1e-6, DeclaredParameters::kNoLimit, "simulated time between two DW steps [s]");
  parameters.declare("t_max", parameters_.t_max, 1, 1000000, "T_max of eq. 4: curve length and re-evaluation delay [steps]");
  parameters.declare("n", parameters_.n, 1, DeclaredParameters::kNoLimit, "n of eq. 4 (T_max^2: one curve spans 0.25)", true);
  parameters.declare("reflex_threshold", parameters_.reflex_threshold, 0, 1,
                     "an upward crossing of this weight triggers the turn-to reflex");
  parameters.declare("reflex_priority", reflex_priority_, 0, 1000000, "priority of the reflex look_at task");
  parameters.declare("reflex", reflex_enabled_, "push reflex tasks at all (0: weights only)");
  parameters.declare("incongruent_c", parameters_.incongruent_c, 0, 1, "a (label, activity) with c >= this rises, others fall");
  parameters.declare("initial_weight", parameters_.initial_weight, 0, 1, "weight of a newly heard object");
  parameters.declare("default_c", default_c_, 0, 1, "c of a (label, activity) pair not in the congruency table");
  parameters.declare("reevaluate", parameters_.reevaluate, "re-evaluate c after more than T_max unchanged steps");
  parameters.declare("min_perceptibility", min_perceptibility_, 0, 1,
                     "an object counts as heard when its a_P is at least this");
  parameters.declare("residual_floor", parameters_.residual_floor, 0, 1,
                     "the lowest weight of an object that has been incongruent");
  parameters.declare("danger_radius", parameters_.danger_radius, 0, DeclaredParameters::kNoLimit,
                     "a person this close to a hazard (centre to centre) is endangered: c = incongruent_c; 0: off [m]");
  parameters.declare("danger_labels", danger_labels_, "labels of hazards, comma-separated (a hazard's pair has c >= incongruent_c)");
}

void DwExpert::onStartUp() {
  step_us_ = static_cast<int64_t>(std::llround(step_s_ * 1e6));
  parameters_.danger_labels.clear();
  std::stringstream labels(danger_labels_);
  for (std::string label; std::getline(labels, label, ',');)
    if (!label.empty()) parameters_.danger_labels.push_back(label);
  CongruencyTable table;
  table.setDefaultValue(default_c_);
  dw_ = std::make_unique<DynamicWeighting>(parameters_, table);
}

bool DwExpert::stepDue(int64_t utime) const { return stepIndex(utime, step_us_) > last_step_index_; }

bool DwExpert::inputsReady(const expert::Firing& firing) const {
  if (!robot_.has(firing.tick) || !scene_.has(firing.tick)) return false;
  if (stepDue(firing.utime) && (!audio_.has(firing.tick) || !labels_.has(firing.tick))) return false;
  // The stack of the previous tick (tasks fire last), while the stack publishes.
  if (const auto* stack = stack_.latest(); stack != nullptr && stack->tick >= firing.tick - 2 &&
                                            stack->tick < firing.tick - 1)
    return false;
  return true;
}

void DwExpert::adoptTable(const scene_objects_t& scene) {
  std::vector<std::tuple<std::string, std::string, double>> entries;
  for (const auto& entry : scene.congruency) entries.emplace_back(entry.label, entry.activity, entry.value);
  if (entries == adopted_entries_) return;
  adopted_entries_ = entries;
  CongruencyTable table;  // the defaults, overridden and extended by the scenario
  table.setDefaultValue(default_c_);
  for (const auto& [label, activity, value] : entries) {
    try {
      table.set(label, activity, value);
    } catch (const std::invalid_argument& e) {
      log::warn("GT_OBJECTS congruency entry ignored: ", e.what());
    }
  }
  dw_->setTable(table);
}

std::vector<Stimulus> DwExpert::stimuliOf(const acoustic_percepts_t& audio, const labels_t* labels) const {
  std::vector<Stimulus> stimuli;
  for (const auto& percept : audio.percepts) {
    Stimulus s;
    s.object_id = percept.object_id;
    s.activity = percept.activity;
    s.x = percept.est_x;
    s.y = percept.est_y;
    s.label = percept.acoustic_label;  // used when the labels cannot tell
    const object_labels_t* estimate = nullptr;
    if (labels != nullptr)
      for (const auto& object : labels->objects)
        if (object.object_id == percept.object_id) estimate = &object;
    if (estimate != nullptr) {
      if (estimate->perceptibility < min_perceptibility_) continue;
      // Estimated label: the category with the highest L_j (eq. 3); a tie
      // (nothing heard clearly) leaves the audio expert's label.
      int best = -1;
      bool tie = false;
      const std::size_t n = std::min(estimate->categories.size(), estimate->confidence.size());
      for (std::size_t j = 0; j < n; ++j) {
        if (best < 0 || estimate->confidence[j] > estimate->confidence[best] + 1e-12) {
          best = static_cast<int>(j);
          tie = false;
        } else if (std::abs(estimate->confidence[j] - estimate->confidence[best]) <= 1e-12) {
          tie = true;
        }
      }
      if (best >= 0 && !tie) s.label = estimate->categories[best];
    } else if (min_perceptibility_ > 0) {
      continue;  // not labelled: not heard well enough
    }
    stimuli.push_back(std::move(s));
  }
  return stimuli;
}

// The direction DW would have the head face: towards the object with the
// highest weight at or above the reflex threshold; NaN when there is none.
double DwExpert::viewingDirection(const robot_state_t* robot) const {
  const ObjectWeight* heaviest = nullptr;
  for (const auto& object : dw_->objects())
    if (object.weight >= parameters_.reflex_threshold && (!heaviest || object.weight > heaviest->weight))
      heaviest = &object;
  if (heaviest == nullptr || robot == nullptr) return std::nan("");
  return model::wrapDegrees(std::atan2(heaviest->y - robot->y, heaviest->x - robot->x) * 180.0 / M_PI);
}

expert::Outcome DwExpert::fire(const expert::Firing& firing, expert::Output& out) {
  if (!dw_) startUp();
  const auto* scene = scene_.ofTick(firing.tick);
  if (scene == nullptr) scene = scene_.latest();
  if (scene != nullptr) adoptTable(*scene);

  if (stepDue(firing.utime)) {
    last_step_index_ = stepIndex(firing.utime, step_us_);
    const auto* audio = audio_.ofTick(firing.tick);
    if (audio == nullptr) {
      // Not a failure of this expert (the arbiter would retry the tick): the
      // step hears nothing, so every weight is kept.
      log::warn("tick ", firing.tick, ": no AUDIO of this tick, DW step with nothing heard");
      dw_->step({});
    } else {
      const auto triggers = dw_->step(stimuliOf(*audio, labels_.ofTick(firing.tick)));
      for (const auto& trigger : triggers) {
        attended_object_ = trigger.object_id;
        log::info("turn-to reflex: ", trigger.object_id, " weight ", fmt(trigger.weight_before), " -> ",
                  fmt(trigger.weight_after), " at t = ", fmt(firing.utime / 1e6), " s");
        if (!reflex_enabled_) continue;
        tasks::Task look;
        look.kind = tasks::kinds::kLookAt;
        look.priority = reflex_priority_;
        look.object_id = trigger.object_id;
        look.x = trigger.x;
        look.y = trigger.y;
        look.yaw = 0;
        look.origin = "dw";
        look.note = "turn-to reflex: " + trigger.object_id + " weight " + fmt(trigger.weight_after);
        task_command_out_.publish(out, tasks::pushCommand(look, firing.utime, next_command_id_++));
      }
    }
  }

  dynamic_weights_t message{};
  message.utime = firing.utime;
  message.tick = firing.tick;
  const auto* robot = robot_.ofTick(firing.tick);
  if (robot == nullptr) robot = robot_.latest();
  message.viewing_direction = viewingDirection(robot);
  const auto* stack = stack_.latest();
  if (stack != nullptr && !stack->tasks.empty()) {
    const auto top = tasks::fromMessage(stack->tasks.front());
    message.current_task = tasks::describe(top);
  } else {
    message.current_task = stack != nullptr ? "idle" : "";
  }
  message.attended_object = attended_object_;
  for (const auto& object : dw_->objects()) {
    object_weight_t w;
    w.object_id = object.object_id;
    w.weight = object.weight;
    w.congruency = object.congruency;
    w.rising = object.rising;
    w.step = object.step;
    w.label = object.label;
    w.activity = object.activity;
    w.sounding = object.sounding;
    message.weights.push_back(w);
  }
  message.num_weights = static_cast<int32_t>(message.weights.size());
  dynamic_weights_out_.publish(out, message);
  return expert::Outcome::success();
}

}  // namespace beft::dw

#include "dw_expert.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <beft/dynamic_weights_t.hpp>
#include <beft/task_command_t.hpp>

#include "channels.hpp"
#include "log.hpp"
#include "model.hpp"
#include "task.hpp"
#include "task_messages.hpp"

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
         "otherwise; a higher c makes it jump to c; a silent object keeps its weight. Turn-to "
         "reflex: when a weight crosses reflex_threshold upward, a look_at task for that object is "
         "pushed on TASK_COMMAND with priority reflex_priority. Publishes DYNAMIC_WEIGHTS every tick "
         "(every weight, the viewing direction from ROBOT_STATE, the current task from TASK_STACK).";
}

std::vector<expert::ChannelSpec> DwExpert::reads() const {
  return {{channels::kAudio, "beft.acoustic_percepts_t"},
          {channels::kLabelsAcoustic, "beft.labels_t"},
          {channels::kGroundTruth, "beft.scene_objects_t"},
          {channels::kRobotState, "beft.robot_state_t"},
          {channels::kTaskStack, "beft.task_stack_t"}};
}

std::vector<expert::ChannelSpec> DwExpert::writes() const {
  return {{channels::kDynamicWeights, "beft.dynamic_weights_t"}, {channels::kTaskCommand, "beft.task_command_t"}};
}

std::vector<std::vector<std::string>> DwExpert::parameterHelp() const {
  return {{"dw_step_s", "0.5", "simulated time between two DW steps [s]"},
          {"t_max", "10", "T_max of eq. 4: curve length and re-evaluation delay [steps]"},
          {"n", "100", "n of eq. 4 (T_max^2: one curve spans 0.25)"},
          {"reflex_threshold", "0.75", "an upward crossing of this weight triggers the turn-to reflex"},
          {"reflex_priority", "100", "priority of the reflex look_at task"},
          {"reflex", "1", "push reflex tasks at all (0: weights only)"},
          {"incongruent_c", "0.75", "a (label, activity) with c >= this rises, others fall"},
          {"initial_weight", "0.5", "weight of a newly heard object"},
          {"default_c", "0.5", "c of a (label, activity) pair not in the congruency table"},
          {"reevaluate", "1", "re-evaluate c after more than T_max unchanged steps"},
          {"min_perceptibility", "0", "an object counts as heard when its a_P is at least this"}};
}

void DwExpert::onStartUp(const expert::Parameters& p) {
  const double step_s = p.getDouble("dw_step_s", 0.5);
  if (!(step_s > 0) || !std::isfinite(step_s)) throw std::invalid_argument("dw_step_s must be > 0");
  step_us_ = static_cast<int64_t>(std::llround(step_s * 1e6));
  if (step_us_ <= 0) throw std::invalid_argument("dw_step_s must be at least 1 us");
  parameters_.t_max = static_cast<int>(p.getInt("t_max", 10));
  parameters_.n = p.getDouble("n", 100);
  parameters_.reflex_threshold = p.getDouble("reflex_threshold", 0.75);
  parameters_.incongruent_c = p.getDouble("incongruent_c", 0.75);
  parameters_.initial_weight = p.getDouble("initial_weight", 0.5);
  parameters_.reevaluate = p.getBool("reevaluate", true);
  reflex_priority_ = static_cast<int32_t>(p.getInt("reflex_priority", 100));
  reflex_enabled_ = p.getBool("reflex", true);
  default_c_ = p.getDouble("default_c", 0.5);
  min_perceptibility_ = p.getDouble("min_perceptibility", 0.0);
  if (parameters_.t_max < 1) throw std::invalid_argument("t_max must be >= 1");
  if (!(parameters_.n > 1)) throw std::invalid_argument("n must be > 1");
  if (!(parameters_.initial_weight >= 0 && parameters_.initial_weight <= 1))
    throw std::invalid_argument("initial_weight must be in [0, 1]");
  if (!(default_c_ >= 0 && default_c_ <= 1)) throw std::invalid_argument("default_c must be in [0, 1]");
  CongruencyTable table;
  table.setDefaultValue(default_c_);
  dw_ = std::make_unique<DynamicWeighting>(parameters_, table);
}

bool DwExpert::onMessage(const std::string& channel, const void* data, int size) {
  if (channel == channels::kAudio) return audio_.store(data, size);
  if (channel == channels::kLabelsAcoustic) return labels_.store(data, size);
  if (channel == channels::kGroundTruth) return scene_.store(data, size);
  if (channel == channels::kRobotState) return robot_.store(data, size);
  if (channel == channels::kTaskStack) return stack_.store(data, size);
  return false;
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

expert::Outcome DwExpert::fire(const expert::Firing& firing, expert::Output& out) {
  if (!dw_) onStartUp({});
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
        task_command_t command;
        command.utime = firing.utime;
        command.command_id = next_command_id_++;
        command.command = task_command_t::COMMAND_PUSH;
        tasks::Task look;
        look.kind = tasks::kinds::kLookAt;
        look.priority = reflex_priority_;
        look.object_id = trigger.object_id;
        look.x = trigger.x;
        look.y = trigger.y;
        look.yaw = 0;
        look.origin = "dw";
        look.note = "turn-to reflex: " + trigger.object_id + " weight " + fmt(trigger.weight_after);
        command.task = tasks::toMessage(look);
        out.publish(channels::kTaskCommand, command);
      }
    }
  }

  dynamic_weights_t message;
  message.utime = firing.utime;
  message.tick = firing.tick;
  const auto* robot = robot_.ofTick(firing.tick);
  if (robot == nullptr) robot = robot_.latest();
  message.viewing_direction = robot ? model::wrapDegrees(robot->yaw + robot->head_yaw) : 0.0;
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
  out.publish(channels::kDynamicWeights, message);
  return expert::Outcome::success();
}

}  // namespace beft::dw

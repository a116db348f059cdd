// The dynamic-weighting expert as a process (high level, fired once per tick
// after fusion): steps DynamicWeighting every dw_step_s of simulated time from
// AUDIO and LABELS_ACOUSTIC, pushes a look_at task on TASK_COMMAND when a
// weight crosses the reflex threshold upward, and publishes DYNAMIC_WEIGHTS
// every tick.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/labels_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/task_stack_t.hpp>

#include "experts/dw/dynamic_weighting.hpp"
#include "lib/expert/expert.hpp"
#include "lib/expert/scene_input.hpp"

namespace beft::dw {

class DwExpert : public expert::Expert {
 public:
  std::string name() const override { return "dw"; }
  std::string description() const override;
  bool inputsReady(const expert::Firing& firing) const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 protected:
  void declareParameters(DeclaredParameters& parameters) override;
  void onStartUp() override;

 private:
  bool stepDue(int64_t utime) const;
  double viewingDirection(const robot_state_t* robot) const;
  std::vector<Stimulus> stimuliOf(const acoustic_percepts_t& audio, const labels_t* labels) const;
  void adoptTable(const scene_objects_t& scene);

  DwParameters parameters_;
  double step_s_ = 0.5;  // simulated time between two DW steps [s]
  int64_t step_us_ = 0;  // the same in microseconds, from step_s_ at start-up
  int32_t reflex_priority_ = 100;
  bool reflex_enabled_ = true;
  double default_c_ = 0.5;
  double min_perceptibility_ = 0.0;
  std::string danger_labels_ = "fire";  // comma-separated
  std::unique_ptr<DynamicWeighting> dw_;
  int64_t last_step_index_ = std::numeric_limits<int64_t>::min();
  std::vector<std::tuple<std::string, std::string, double>> adopted_entries_;  // scenario table in use
  std::string attended_object_;
  int64_t next_command_id_ = 1;

  expert::TickInput<acoustic_percepts_t> audio_{*this, channels::kAudio};
  expert::TickInput<labels_t> labels_{*this, channels::kLabelsAcoustic};
  expert::SceneInput scene_{*this};
  expert::TickInput<robot_state_t> robot_{*this, channels::kRobotState};
  expert::TickInput<task_stack_t> stack_{*this, channels::kTaskStack, 4};
  expert::OutputPort<dynamic_weights_t> dynamic_weights_out_{*this, channels::kDynamicWeights};
  expert::OutputPort<task_command_t> task_command_out_{*this, channels::kTaskCommand};
};

}  // namespace beft::dw

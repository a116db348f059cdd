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

#include "dynamic_weighting.hpp"
#include "expert.hpp"
#include "tick_channel.hpp"

namespace beft::dw {

class DwExpert : public expert::Expert {
 public:
  std::string name() const override { return "dw"; }
  std::string description() const override;
  std::vector<expert::ChannelSpec> reads() const override;
  std::vector<expert::ChannelSpec> writes() const override;
  std::vector<std::vector<std::string>> parameterHelp() const override;
  void onStartUp(const expert::Parameters& parameters) override;
  bool onMessage(const std::string& channel, const void* data, int size) override;
  bool inputsReady(const expert::Firing& firing) const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 private:
  bool stepDue(int64_t utime) const;
  std::vector<Stimulus> stimuliOf(const acoustic_percepts_t& audio, const labels_t* labels) const;
  void adoptTable(const scene_objects_t& scene);

  DwParameters parameters_;
  int64_t step_us_ = 500000;
  int32_t reflex_priority_ = 100;
  bool reflex_enabled_ = true;
  double default_c_ = 0.5;
  double min_perceptibility_ = 0.0;
  std::unique_ptr<DynamicWeighting> dw_;
  int64_t last_step_index_ = std::numeric_limits<int64_t>::min();
  std::vector<std::tuple<std::string, std::string, double>> adopted_entries_;  // scenario table in use
  std::string attended_object_;
  int64_t next_command_id_ = 1;

  expert::TickChannel<acoustic_percepts_t> audio_;
  expert::TickChannel<labels_t> labels_;
  expert::TickChannel<scene_objects_t> scene_{4};
  expert::TickChannel<robot_state_t> robot_;
  expert::TickChannel<task_stack_t> stack_{4};
};

}  // namespace beft::dw

// The task stack as a process (high level, fired once per tick, last): applies
// the TASK_COMMANDs received since the last firing in arrival order, lets the
// executor run the top task, and publishes ROBOT_CMD, TASK_STACK, TASK_EVENTS
// and PLAN_REQUEST. A plan request waits for its PLAN_RESULT until the next
// firing (inputsReady, bounded by the process's --ready-timeout).
#pragma once

#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/obstacle_map_t.hpp>
#include <beft/plan_result_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/task_command_t.hpp>

#include "executor.hpp"
#include "expert.hpp"
#include "task_stack.hpp"
#include "tick_channel.hpp"

namespace beft::tasks {

class TasksExpert : public expert::Expert {
 public:
  std::string name() const override { return "tasks"; }
  std::string description() const override;
  std::vector<expert::ChannelSpec> reads() const override;
  std::vector<expert::ChannelSpec> writes() const override;
  std::vector<std::vector<std::string>> parameterHelp() const override;
  void onStartUp(const expert::Parameters& parameters) override;
  bool onMessage(const std::string& channel, const void* data, int size) override;
  bool inputsReady(const expert::Firing& firing) const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 private:
  void applyCommand(const task_command_t& command);
  void updateExecutorInputs(const expert::Firing& firing);
  void logEvents(const std::vector<TaskEvent>& events) const;

  std::unique_ptr<TaskStack> stack_;
  std::unique_ptr<Executor> executor_;
  static constexpr std::size_t kMaxQueuedCommands = 10000;
  std::vector<task_command_t> commands_;        // received since the last firing, in order
  int64_t dropped_commands_ = 0;                // beyond kMaxQueuedCommands
  std::deque<plan_result_t> plan_results_;      // recent answers of the planner service
  expert::TickChannel<robot_state_t> robot_;
  expert::TickChannel<hypotheses_t> hypotheses_{4};
  expert::TickChannel<acoustic_percepts_t> audio_{4};
  expert::TickChannel<obstacle_map_t> map_{2};
  int64_t map_utime_ = -1;  // the obstacle map last given to the executor
  std::optional<obstacle_map_t> last_map_;  // as last decoded
  bool map_warned_ = false;
};

}  // namespace beft::tasks

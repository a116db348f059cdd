// The task stack as a process (high level, fired once per tick, last): applies
// the TASK_COMMANDs received since the last firing (ordered by their task's
// origin, then by arrival), lets the
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

#include "experts/tasks/executor.hpp"
#include "lib/expert/expert.hpp"
#include "lib/expert/hypotheses_input.hpp"
#include "lib/expert/obstacle_map_input.hpp"
#include "lib/task/task_stack.hpp"

namespace beft::tasks {

class TasksExpert : public expert::Expert {
 public:
  std::string name() const override { return "tasks"; }
  std::string description() const override;
  bool inputsReady(const expert::Firing& firing) const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 protected:
  void declareParameters(DeclaredParameters& parameters) override;
  void onStartUp() override;

 private:
  void onCommand(task_command_t&& command);
  void onPlanResult(plan_result_t&& result);
  void applyCommand(const task_command_t& command);
  void updateExecutorInputs(const expert::Firing& firing);
  void logEvents(const std::vector<TaskEvent>& events) const;

  std::unique_ptr<TaskStack> stack_;
  std::unique_ptr<Executor> executor_;
  static constexpr std::size_t kMaxQueuedCommands = 10000;
  std::vector<task_command_t> commands_;        // received since the last firing, in order
  int64_t dropped_commands_ = 0;                // beyond kMaxQueuedCommands
  std::deque<plan_result_t> plan_results_;      // recent answers of the planner service
  ExecutorParameters executor_parameters_;
  StackOptions stack_options_;
  expert::HandledInput<task_command_t> commands_in_{
      *this, channels::kTaskCommand, [this](task_command_t&& command) { onCommand(std::move(command)); }};
  expert::HandledInput<plan_result_t> plan_results_in_{
      *this, channels::kPlanResult, [this](plan_result_t&& result) { onPlanResult(std::move(result)); }};
  expert::TickInput<robot_state_t> robot_{*this, channels::kRobotState};
  expert::HypothesesInput hypotheses_{*this};
  expert::TickInput<acoustic_percepts_t> audio_{*this, channels::kAudio, 4};
  expert::ObstacleMapInput map_{*this};
  uint64_t map_version_ = 0;  // the obstacle map last given to the executor
  bool map_warned_ = false;
  expert::OutputPort<robot_command_t> robot_command_out_{*this, channels::kRobotCommand};
  expert::OutputPort<task_stack_t> task_stack_out_{*this, channels::kTaskStack};
  expert::OutputPort<task_events_t> task_events_out_{*this, channels::kTaskEvents};
  expert::OutputPort<plan_request_t> plan_request_out_{*this, channels::kPlanRequest};
};

}  // namespace beft::tasks

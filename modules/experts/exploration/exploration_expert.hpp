// The exploration expert as a process (high level, fired once per tick after
// dynamic weighting): stores HYPOTHESES, OBSTACLE_MAP, ROBOT_STATE,
// TASK_STACK, DYNAMIC_WEIGHTS and GT_OBJECTS (for the scenario's duration
// only: never positions or labels), runs the Explorer, and publishes its task
// changes on TASK_COMMAND and, when the mission is over, STOP_REQUEST.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <beft/dynamic_weights_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/obstacle_map_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/task_command_t.hpp>
#include <beft/task_stack_t.hpp>

#include "experts/exploration/explorer.hpp"
#include "lib/expert/expert.hpp"
#include "lib/expert/hypotheses_input.hpp"
#include "lib/expert/obstacle_map_input.hpp"
#include "lib/expert/scene_input.hpp"

namespace beft::exploration {

// What the Explorer sees of one hypothesis: hypothesis_t with the DW weight.
HypothesisView viewOf(const hypothesis_t& hypothesis, const dynamic_weights_t* weights);
// A request of the Explorer as a TASK_COMMAND (command_id and utime not set).
task_command_t commandOf(const TaskRequest& request, const std::string& origin);

class ExplorationExpert : public expert::Expert {
 public:
  std::string name() const override { return "exploration"; }
  std::string description() const override;
  bool inputsReady(const expert::Firing& firing) const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 protected:
  void declareParameters(DeclaredParameters& parameters) override;
  void onStartUp() override;

 private:
  Observation observe(const expert::Firing& firing);

  ExplorerParameters parameters_;
  std::unique_ptr<Explorer> explorer_;
  int64_t next_command_id_ = 1;
  int64_t map_version_ = 0;  // counts the different maps taken
  std::shared_ptr<const planners::ObstacleCells> map_;
  bool map_warned_ = false;

  expert::TickInput<robot_state_t> robot_{*this, channels::kRobotState};
  expert::HypothesesInput hypotheses_{*this};
  expert::TickInput<dynamic_weights_t> weights_{*this, channels::kDynamicWeights, 4};
  expert::ObstacleMapInput map_messages_{*this};
  expert::TickInput<task_stack_t> stack_{*this, channels::kTaskStack, 4};
  expert::SceneInput scene_{*this};
  expert::OutputPort<task_command_t> task_command_out_{*this, channels::kTaskCommand};
  expert::OutputPort<run_status_t> stop_request_out_{*this, channels::kStopRequest};
};

}  // namespace beft::exploration

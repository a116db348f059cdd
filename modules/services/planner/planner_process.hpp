// beft-planner as a service: answers each PLAN_REQUEST once on PLAN_RESULT,
// on the newest OBSTACLE_MAP, and sends a HEARTBEAT every second and at once
// to an arbiter that waits for it.
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <beft/heartbeat_t.hpp>
#include <beft/obstacle_map_changes_t.hpp>
#include <beft/obstacle_map_t.hpp>
#include <beft/plan_request_t.hpp>
#include <beft/plan_result_t.hpp>
#include <beft/run_status_t.hpp>

#include "lib/wire/obstacle_map_changes.hpp"
#include "services/planner/planner_service.hpp"
#include "lib/service/service.hpp"
#include "lib/transport/control_messages.hpp"
#include "lib/transport/transport.hpp"

namespace beft::planner_service {

class PlannerProcess : public service::Service {
 public:
  std::string name() const override { return "planner"; }
  std::string description() const override;
  void addOptions(CLI::App& app) override;
  void onStartUp() override;
  int serve(service::Context& context) override;

 private:
  // Store only (the ports' handlers): the recent maps as bytes (decoded when
  // a request needs one), requests in arrival order, whether an arbiter waits.
  struct KeptMessage;
  static void keep(std::deque<KeptMessage>& kept, std::size_t most, const transport::Message& message);
  void onRunStatus(const beft::run_status_t& status);
  // The map a request is planned on: that of the newest tick kept whose
  // simulated time is not after the request's (the map of the tick that sent
  // it; a later one may already have arrived when the planner gets to the
  // request, and which one would depend on the machine's load), made from its
  // keyframe and changes; else of the oldest tick kept; null if none. Throws
  // planners::ObstacleMapError if the messages do not make a map.
  std::shared_ptr<const planners::ObstacleCells> mapFor(const beft::plan_request_t& request);
  // Gives the planner this map unless it has it already.
  void useMap(const std::shared_ptr<const planners::ObstacleCells>& map);
  void answerRequests(lcm::LCM& lcm);
  void answerOne(lcm::LCM& lcm, const beft::plan_request_t& request);
  // After a crash: the maps and the requests not yet answered, from the run's log.
  void resumeFromLog(const std::string& log_path, int64_t live_since_us);
  // Answers them, each on its map.
  void answerUnanswered(lcm::LCM& lcm);

  struct UnansweredRequest {
    beft::plan_request_t request;
    std::shared_ptr<const planners::ObstacleCells> map;  // or null
  };
  std::vector<UnansweredRequest> unanswered_;

  ServiceConfig config_;
  std::vector<std::string> pf_params_;
  std::unique_ptr<PlannerService> planner_;
  // Received as bytes, decoded when a request needs them; oldest first.
  static constexpr std::size_t kChangesKept = 64;  // a few seconds of ticks
  static constexpr std::size_t kKeyframesKept = 4;
  struct KeptMessage {
    int64_t utime;  // simulated time [us]
    int64_t tick;
    std::vector<uint8_t> bytes;
  };
  std::deque<KeptMessage> recent_keyframes_;  // OBSTACLE_MAP
  std::deque<KeptMessage> recent_changes_;    // OBSTACLE_MAP_CHANGES
  planners::ObstacleMapAssembler assembler_;
  std::shared_ptr<const planners::ObstacleCells> map_in_use_;  // the last one given to the planner
  bool arbiter_waiting_ = false;
  std::deque<beft::plan_request_t> requests_;
  int64_t answered_ = 0;

  // Maps wait in the kernel until a request wakes the process.
  service::CheckedBytesPort<beft::obstacle_map_t> keyframes_in_{
      *this, channels::kObstacleMap, "keyframes: the whole map",
      [this](const transport::Message& m) { keep(recent_keyframes_, kKeyframesKept, m); },
      service::Receiving().queued()};
  service::CheckedBytesPort<beft::obstacle_map_changes_t> changes_in_{
      *this, channels::kObstacleMapChanges, "a request is planned on the map of its tick",
      [this](const transport::Message& m) { keep(recent_changes_, kChangesKept, m); }, service::Receiving().queued()};
  service::ReadPort<beft::plan_request_t> requests_in_{
      *this, channels::kPlanRequest, "each answered once",
      [this](beft::plan_request_t&& request) { requests_.push_back(std::move(request)); }};
  service::ReadPort<beft::run_status_t> run_status_in_{
      *this, channels::kRunStatus, "an arbiter waiting for heartbeats is answered at once",
      [this](beft::run_status_t&& status) { onRunStatus(status); },
      service::Receiving().only(control::runStatusIn(beft::run_status_t::STATE_WAITING,
                                                     "an arbiter waiting for heartbeats"))};
  service::WritePort<beft::plan_result_t> results_out_{*this, channels::kPlanResult};
  service::WritePort<beft::heartbeat_t> heartbeat_out_{*this, channels::kHeartbeat, "every second"};
};

}  // namespace beft::planner_service

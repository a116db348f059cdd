// beft-planner as a service: answers each PLAN_REQUEST once on PLAN_RESULT,
// on the newest OBSTACLE_MAP, and sends a HEARTBEAT every second and at once
// to an arbiter that waits for it.
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <beft/plan_request_t.hpp>

#include "lib/wire/obstacle_map_changes.hpp"
#include "services/planner/planner_service.hpp"
#include "lib/service/service.hpp"
#include "lib/transport/transport.hpp"

namespace beft::planner_service {

class PlannerProcess : public service::Service {
 public:
  std::string name() const override { return "planner"; }
  std::string description() const override;
  std::vector<service::Port> reads() const override;
  std::vector<service::Port> writes() const override;
  void addOptions(CLI::App& app) override;
  void onStartUp() override;
  int serve(service::Context& context) override;

 private:
  // Store only: the recent maps as bytes (decoded when a request needs one),
  // requests in arrival order, whether an arbiter waits.
  void onMessage(const transport::Message& message);
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
};

}  // namespace beft::planner_service

// beft-planner as a service: answers each PLAN_REQUEST once on PLAN_RESULT,
// on the newest OBSTACLE_MAP, and sends a HEARTBEAT every second and at once
// to an arbiter that waits for it.
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <beft/plan_request_t.hpp>

#include "planner_service.hpp"
#include "service.hpp"
#include "transport.hpp"

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
  // Store only: the newest map as bytes (decoded when a request needs it),
  // requests in arrival order, whether an arbiter waits.
  void onMessage(const transport::Message& message);
  void takeNewestMap();
  void answerRequests(lcm::LCM& lcm);
  // After a crash: the newest map and the requests not yet answered, from the run's log.
  void resumeFromLog(const std::string& log_path, int64_t live_since_us);
  // Answers them, each on the map that was newest when it was sent.
  void answerUnanswered(lcm::LCM& lcm);

  struct UnansweredRequest {
    beft::plan_request_t request;
    std::vector<uint8_t> map;  // encoded obstacle_map_t, or empty
  };
  std::vector<UnansweredRequest> unanswered_;

  ServiceConfig config_;
  std::vector<std::string> pf_params_;
  std::unique_ptr<PlannerService> planner_;
  std::vector<uint8_t> latest_map_;
  bool has_map_ = false;
  bool arbiter_waiting_ = false;
  std::deque<beft::plan_request_t> requests_;
  int64_t answered_ = 0;
};

}  // namespace beft::planner_service

// beft-control's line to a running run's arbiter: sends RUN_CONTROL requests
// as RunControlClient says, again until answered, and follows the answers
// (RUN_CONTROL_STATE) and the run's status (RUN_STATUS: whether it ended).
#pragma once

#include <lcm/lcm-cpp.hpp>

#include <beft/run_control_t.hpp>
#include <beft/run_status_t.hpp>

#include <functional>
#include <optional>
#include <string>

#include "lib/service/run_control_client.hpp"

namespace beft::control_tool {

class ArbiterLink {
 public:
  // Subscribes on the run's channels (this process's run id).
  ArbiterLink(lcm::LCM& lcm, service::RunControlClient& client);
  ~ArbiterLink();
  ArbiterLink(const ArbiterLink&) = delete;
  ArbiterLink& operator=(const ArbiterLink&) = delete;

  // Handles LCM, sending what the client says is due, until `done()` or
  // `timeout_s` has passed; false on timeout or when LCM fails.
  bool waitUntil(const std::function<bool()>& done, double timeout_s);
  // The run's end, if a FINISHED or FAILED status was heard.
  const std::optional<beft::run_status_t>& ended() const { return ended_; }
  // Whether publishing failed (said once on stderr).
  bool publishFailed() const { return publish_failed_; }

 private:
  static void onState(const lcm::ReceiveBuffer* buffer, const std::string& channel, ArbiterLink* self);
  static void onStatus(const lcm::ReceiveBuffer* buffer, const std::string& channel, ArbiterLink* self);
  void sendDue();

  lcm::LCM& lcm_;
  service::RunControlClient& client_;
  lcm::Subscription* state_subscription_ = nullptr;
  lcm::Subscription* status_subscription_ = nullptr;
  std::optional<beft::run_status_t> ended_;
  bool publish_failed_ = false;
};

}  // namespace beft::control_tool

#include "tools/control/arbiter_link.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "lib/common/channels.hpp"
#include "lib/common/clocks.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::control_tool {

ArbiterLink::ArbiterLink(lcm::LCM& lcm, service::RunControlClient& client) : lcm_(lcm), client_(client) {
  state_subscription_ = lcm_.subscribeFunction(wire::runChannel(channels::kRunControlState), &ArbiterLink::onState, this);
  state_subscription_->setQueueCapacity(100);
  status_subscription_ = lcm_.subscribeFunction(wire::runChannel(channels::kRunStatus), &ArbiterLink::onStatus, this);
  status_subscription_->setQueueCapacity(100);
}

ArbiterLink::~ArbiterLink() {
  lcm_.unsubscribe(state_subscription_);
  lcm_.unsubscribe(status_subscription_);
}

// Raw bytes through the message guard: LCM's typed subscribe decodes
// unguarded, and a malformed message would end the tool.
void ArbiterLink::onState(const lcm::ReceiveBuffer* buffer, const std::string& channel, ArbiterLink* self) {
  beft::run_control_t state;
  if (wire::decodeFrom(channel, buffer->data, buffer->data_size, state)) self->client_.onState(state);
}

void ArbiterLink::onStatus(const lcm::ReceiveBuffer* buffer, const std::string& channel, ArbiterLink* self) {
  beft::run_status_t status;
  if (!wire::decodeFrom(channel, buffer->data, buffer->data_size, status)) return;
  if (status.state == beft::run_status_t::STATE_FINISHED || status.state == beft::run_status_t::STATE_FAILED)
    self->ended_ = status;
}

void ArbiterLink::sendDue() {
  const auto request = client_.due(wallMicros());
  if (!request) return;
  if (transport::publish(lcm_, wire::runChannel(channels::kRunControl), *request) != 0 && !publish_failed_) {
    publish_failed_ = true;
    std::fprintf(stderr, "beft-control: error: could not publish on %s\n", channels::kRunControl.name);
  }
}

bool ArbiterLink::waitUntil(const std::function<bool()>& done, double timeout_s) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::microseconds(static_cast<int64_t>(timeout_s * 1e6));
  while (true) {
    sendDue();
    if (done()) return true;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    // Woken at least every 20 ms: a request due again goes out on time.
    if (lcm_.handleTimeout(static_cast<int>(std::min<int64_t>(left, 20))) < 0) return false;
  }
}

}  // namespace beft::control_tool

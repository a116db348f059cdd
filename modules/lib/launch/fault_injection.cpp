#include "lib/launch/fault_injection.hpp"

#include <algorithm>

#include <beft/marking_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/launch/launch_file.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::launch {

PlannedKill parsePlannedKill(const std::string& text) {
  const auto at = text.find('@');
  if (at == std::string::npos || at == 0 || at + 1 == text.size())
    throw LaunchError("--kill '" + text + "' is not NAME@TICK (e.g. fusion@150)");
  PlannedKill kill;
  kill.process = text.substr(0, at);
  try {
    std::size_t used = 0;
    kill.tick = std::stoll(text.substr(at + 1), &used);
    if (used != text.size() - at - 1 || kill.tick < 0) throw std::invalid_argument("bad tick");
  } catch (const std::exception&) {
    throw LaunchError("--kill '" + text + "': the tick must be a number >= 0");
  }
  return kill;
}

TickFollower::TickFollower(const std::string& lcm_url, int64_t run_id)
    : lcm_(std::make_unique<lcm::LCM>(lcm_url)) {
  if (lcm_->good()) lcm_->subscribeFunction(wire::runChannel(channels::kMarking, run_id), &onMarking, this);
}

TickFollower::~TickFollower() = default;

void TickFollower::onMarking(const lcm::ReceiveBuffer* buffer, const std::string& channel, TickFollower* self) {
  beft::marking_t marking{};
  if (wire::decodeFrom(channel, buffer->data, buffer->data_size, marking)) self->tick_ = std::max(self->tick_, marking.tick);
}

int64_t TickFollower::poll() {
  if (lcm_->good())
    while (lcm_->handleTimeout(0) > 0) {
    }
  return tick_;
}

}  // namespace beft::launch

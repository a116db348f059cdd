// A receiver with loss repair and envelopes taken care of: in front of the
// socket (or LCM's own receive thread), before the run filter. For each
// message: the envelope comes off; in a run with a key a message without a
// valid tag is refused and counted; the tracked streams go through the
// StreamTracker (in order, once, gaps asked for); senders' states feed it and
// are not handed on. Its fd() is readable when a message waits or a repair
// request falls due (a timerfd beside the socket, in one epoll set), so a
// process that sleeps on it still asks again on time.
#pragma once

#include <memory>

#include "lib/transport/transport.hpp"

namespace lcm {
class LCM;
}

namespace beft::transport::detail {

// `selection` as on the wire (channels with their run suffix). Repair
// requests go out through `lcm`'s publisher.
std::unique_ptr<Receiver> withRepair(std::unique_ptr<Receiver> inner, lcm::LCM& lcm, const Selection& selection);

}  // namespace beft::transport::detail

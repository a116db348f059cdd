// What a comparison of two runs may leave out of one run's log, each named
// and counted so that a reader sees what was not compared.
#pragma once

#include <cstddef>
#include <vector>

#include "lib/compare/run_log.hpp"

namespace beft::compare {

// The log without the data messages the message guard refuses (traffic
// injected on purpose, never a message of the run); `refused`: how many.
std::vector<LoggedMessage> withoutRefused(const std::vector<LoggedMessage>& log, std::size_t& refused);

// The log without the data messages that repeat, byte for byte, an earlier
// message of their channel: what a process killed and restarted mid-tick
// (or an arbiter resuming firings in flight) sends again for that tick. A
// re-sent message that differs stays, and is a difference. `repeats`: how many.
std::vector<LoggedMessage> withoutRepeats(const std::vector<LoggedMessage>& log, std::size_t& repeats);

}  // namespace beft::compare

// The control plane's messages as the arbiter writes them (FIRE, RUN_STATUS),
// and the rules that pick them out on a receiver by their encoded bytes, side
// by side: a change to how one is written shows here, next to the byte
// offsets that depend on it (tests/lib/transport checks both together).
#pragma once

#include <cstdint>
#include <string>

#include <beft/fire_t.hpp>
#include <beft/run_status_t.hpp>

#include "lib/transport/transport.hpp"

namespace beft::control {

beft::fire_t makeFire(const std::string& expert, const std::string& transition, int64_t tick, int64_t utime,
                      int64_t firing_id);
beft::run_status_t makeRunStatus(int8_t state, int64_t tick, int64_t utime, const std::string& message);

// FIRE messages addressed to one expert: fire_t encodes utime (8 bytes) and
// then the expert's name as an LCM string (big-endian length with the NUL,
// the bytes, the NUL).
transport::Rule firesFor(const std::string& expert);

// RUN_STATUS messages in one state: run_status_t encodes utime and tick (8
// bytes each) and then its state byte. `what` names them for the log.
transport::Rule runStatusIn(int8_t state, const std::string& what);

}  // namespace beft::control

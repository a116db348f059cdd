// A restarted arbiter's state, read from the run's log (crash-only).
#pragma once

#include <optional>
#include <string>

#include "services/arbiter/arbiter_core.hpp"

namespace beft::arbiter {

// The last MARKING in the log, the highest firing id and the last
// RUN_CONTROL_STATE (a held run holds again); nothing if the log
// holds no MARKING (the run had not begun: start afresh). Waits up to
// timeout_s for the log to catch up with since_us (the restart).
std::optional<ResumePoint> readResumePoint(const std::string& log_path, int64_t since_us, double timeout_s);

}  // namespace beft::arbiter

// A fault run's data messages against the clean run's, as the benchmark's
// table says it: lib/compare, with the refused (injected) messages left out
// and counted.
#pragma once

#include <cstdint>
#include <string>

#include "lib/compare/run_log.hpp"

namespace beft::bench {

// The clean run's messages, read once (run_id 0: the run of the log's arbiter).
std::vector<compare::LoggedMessage> dataMessages(const std::string& log_path, int64_t run_id);

// "yes", or "no: " and the first difference ("VISION message #12 (tick 12, ...): bytes differ");
// either followed by how many refused messages the run's log held.
std::string compareRuns(const std::vector<compare::LoggedMessage>& clean, const std::string& log_path,
                        int64_t run_id);

}  // namespace beft::bench

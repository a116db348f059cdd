// The last MARKING a recorded run's arbiter published, to draw the net as
// the run left it.
#pragma once

#include <optional>
#include <string>

#include "lib/petri/net_dot.hpp"

namespace beft::net_draw {

// The newest marking_t of the log's run (or of run_id, hex, when given);
// nullopt when the log holds none. Throws std::runtime_error when the log
// cannot be read. Damaged records are skipped.
std::optional<arbiter::ShownMarking> lastMarkingOfRun(const std::string& log_path, const std::string& run_id = "");

}  // namespace beft::net_draw

// beft-new-expert's command line and its --help.
#pragma once

#include <optional>

#include "tools/new_expert/expert_spec.hpp"

namespace beft::new_expert {

// Fills request from argv; an exit code when the program should end here
// (0 after --help, CLI11's code for a bad command line).
std::optional<int> parseCommandLine(int argc, char** argv, ExpertRequest& request);

}  // namespace beft::new_expert

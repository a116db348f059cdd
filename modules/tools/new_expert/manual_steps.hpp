// What `beft-new-expert` prints after writing an expert: the steps left to
// do by hand, with the exact text of each (the nets, the launch file, the
// channel table for a new channel, then build, test and run it alone).
#pragma once

#include <string>
#include <vector>

#include "tools/new_expert/expert_files.hpp"
#include "tools/new_expert/expert_spec.hpp"

namespace beft::new_expert {

std::string manualSteps(const ExpertSpec& spec, const std::vector<GeneratedFile>& written);

}  // namespace beft::new_expert

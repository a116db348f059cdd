// The values of the templates' holes for one expert: its names, and the
// lines that differ with the channels it reads and writes (includes, port
// members, the checks and publishing of fire(), what its test delivers and
// expects).
#pragma once

#include <map>
#include <string>

#include "tools/new_expert/expert_spec.hpp"

namespace beft::new_expert {

std::map<std::string, std::string> templateValues(const ExpertSpec& spec);

// The port member of a channel the expert reads ("robot_state_"; "scene_"
// for GT_OBJECTS, read through expert::SceneInput) or writes ("geometry_out_").
std::string inputMember(const KnownChannel& channel);
std::string outputMember(const KnownChannel& channel);

}  // namespace beft::new_expert

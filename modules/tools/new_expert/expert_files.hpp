// The files of a new expert: its folder under modules/experts/, its tests
// under tests/experts/, and the .lcm of each new channel's message type.
#pragma once

#include <string>
#include <vector>

#include "tools/new_expert/expert_spec.hpp"

namespace beft::new_expert {

struct GeneratedFile {
  std::string path;  // relative to the root, e.g. "modules/experts/threat/CMakeLists.txt"
  std::string text;
};

std::vector<GeneratedFile> expertFiles(const ExpertSpec& spec);

// Writes every file under root, creating folders; SpecError, before any is
// written, if one of them exists.
void writeFiles(const std::string& root, const std::vector<GeneratedFile>& files);

}  // namespace beft::new_expert

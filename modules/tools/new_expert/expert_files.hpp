// The files of a new expert: its folder under modules/experts/, its tests
// under tests/experts/, and the .lcm of each new channel's message type.
#pragma once

#include <optional>
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
// written, if one of them exists. A kill cannot leave it half done: the
// files and `steps` (what the run prints) go to a staging folder under root,
// marked complete once all are there, then each file is moved into place.
void writeFiles(const std::string& root, const std::vector<GeneratedFile>& files, const std::string& steps);

// What a killed run left: a staging folder not marked complete (killed while
// writing) is removed, and nothing is returned; one marked complete (killed
// while moving) has its files not yet in place moved there, and its steps
// are returned, as the killed run would have printed them.
std::optional<std::string> finishInterruptedWrite(const std::string& root);

}  // namespace beft::new_expert

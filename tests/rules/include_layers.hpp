// The layers of the source tree, as rules over include lines: which folder a
// file may include from. Read by test_layers (the tree obeys them) and by
// the README's folder table.
//
//   lib/X       -> lib/*                        (the foundation)
//   planners    -> lib/*, planners
//   blackboard  -> lib/*, blackboard
//   sim/X       -> lib/*, sim/*
//   experts/X   -> lib/*, planners, experts/X   (never another expert, never sim)
//   services/X  -> lib/*, planners, services/X
//   tools/X     -> everything above, tools/X    (never another tool)
//
// Every quoted include names its header from the repository root or from
// modules/ ("lib/expert/ports.hpp", "planners/planner.hpp"); the only bare
// name allowed is a header beside the including file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace beft::layers {

struct IncludeViolation {
  std::string file;      // relative to the repository root
  int line = 0;          // 1-based
  std::string included;  // as written between the quotes
  std::string reason;
};

// The folder's layer of a path relative to the repository root, e.g.
// "modules/experts/audio/x.cpp" -> "experts/audio", "planners/bench/y.hpp"
// -> "planners"; empty for files outside the layered folders.
std::string layerOf(const std::string& relative_path);

// Whether a file in layer `from` may include a header in layer `to`.
bool mayInclude(const std::string& from, const std::string& to);

// Every quoted include of the C++ files under modules/, blackboard/ and
// planners/ checked against the rules, and every bare include under tests/
// that names a header of the source tree not beside the including file.
std::vector<IncludeViolation> checkIncludes(const std::filesystem::path& repository_root);

std::string describe(const IncludeViolation& violation);  // "file:line: ..."

}  // namespace beft::layers

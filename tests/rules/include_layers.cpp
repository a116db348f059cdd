#include "tests/rules/include_layers.hpp"

#include <algorithm>
#include <fstream>
#include <regex>

namespace beft::layers {
namespace fs = std::filesystem;

namespace {

std::string groupOf(const std::string& layer) { return layer.substr(0, layer.find('/')); }

bool isSourceFile(const fs::path& path) {
  const std::string extension = path.extension().string();
  return extension == ".cpp" || extension == ".hpp" || extension == ".h" || extension == ".cc";
}

// The header an include line names, relative to the repository root, or
// empty when it is not in the source tree (a generated or system header).
std::string locate(const fs::path& root, const std::string& included) {
  for (const char* base : {"", "modules"}) {
    const fs::path candidate = fs::path(base) / included;
    if (fs::is_regular_file(root / candidate)) return candidate.lexically_normal().generic_string();
  }
  return {};
}

struct QuotedInclude {
  int line;
  std::string included;
};

std::vector<QuotedInclude> quotedIncludes(const fs::path& file) {
  static const std::regex kInclude(R"(^\s*#\s*include\s+"([^"]+)\")");
  std::vector<QuotedInclude> found;
  std::ifstream in(file);
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    std::smatch match;
    if (std::regex_search(text, match, kInclude)) found.push_back({line, match[1].str()});
  }
  return found;
}

// Header file names of the source tree, to tell a bare include of one of
// them from one of a generated header.
std::vector<std::string> sourceHeaderNames(const fs::path& root) {
  std::vector<std::string> names;
  for (const char* top : {"modules", "blackboard", "planners", "tests"}) {
    if (!fs::is_directory(root / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      if (entry.is_regular_file() && isSourceFile(entry.path())) names.push_back(entry.path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

void checkFile(const fs::path& root, const fs::path& file, const std::vector<std::string>& header_names,
               std::vector<IncludeViolation>& violations) {
  const std::string relative = fs::relative(file, root).generic_string();
  const std::string from = layerOf(relative);
  for (const QuotedInclude& include : quotedIncludes(file)) {
    auto report = [&](std::string reason) {
      violations.push_back({relative, include.line, include.included, std::move(reason)});
    };
    if (include.included.find('/') == std::string::npos) {
      if (fs::is_regular_file(file.parent_path() / include.included)) continue;  // beside its own file
      if (std::binary_search(header_names.begin(), header_names.end(), include.included)) {
        report("a bare name: say where the header lives (from the repository root or modules/)");
      }
      continue;
    }
    if (from.empty()) continue;  // tests and the rest: only bare names are checked
    const std::string located = locate(root, include.included);
    if (located.empty()) {
      report("not found from the repository root or modules/");
      continue;
    }
    const std::string to = layerOf(located);
    if (!to.empty() && !mayInclude(from, to)) report(from + " may not include " + to);
  }
}

}  // namespace

std::string layerOf(const std::string& relative_path) {
  const fs::path path(relative_path);
  std::vector<std::string> parts;
  for (const auto& part : path) parts.push_back(part.string());
  if (parts.size() < 2) return {};
  if (parts[0] == "blackboard" || parts[0] == "planners") return parts[0];
  if (parts[0] == "modules" && parts.size() >= 4) return parts[1] + "/" + parts[2];
  return {};
}

bool mayInclude(const std::string& from, const std::string& to) {
  if (from == to) return true;
  const std::string from_group = groupOf(from), to_group = groupOf(to);
  if (to_group == "lib") return true;  // everything stands on lib
  if (from_group == "lib") return false;
  if (from_group == "planners" || from_group == "blackboard") return false;
  if (from_group == "sim") return to_group == "sim";
  if (from_group == "experts" || from_group == "services") return to_group == "planners";
  if (from_group == "tools") return to_group != "tools";
  return false;
}

std::vector<IncludeViolation> checkIncludes(const fs::path& repository_root) {
  const std::vector<std::string> header_names = sourceHeaderNames(repository_root);
  std::vector<IncludeViolation> violations;
  std::vector<fs::path> files;
  for (const char* top : {"modules", "blackboard", "planners", "tests"}) {
    if (!fs::is_directory(repository_root / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(repository_root / top)) {
      if (entry.is_regular_file() && isSourceFile(entry.path())) files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) checkFile(repository_root, file, header_names, violations);
  return violations;
}

std::string describe(const IncludeViolation& violation) {
  return violation.file + ":" + std::to_string(violation.line) + ": #include \"" + violation.included +
         "\": " + violation.reason;
}

}  // namespace beft::layers

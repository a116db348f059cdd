#include "tools/new_expert/expert_files.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "tools/new_expert/code_blocks.hpp"
#include "tools/new_expert/expert_templates.hpp"

namespace beft::new_expert {

namespace fs = std::filesystem;

std::vector<GeneratedFile> expertFiles(const ExpertSpec& spec) {
  const auto values = templateValues(spec);
  const std::string code = "modules/experts/" + spec.name + "/";
  const std::string tests = "tests/experts/" + spec.name + "/";
  std::vector<GeneratedFile> files = {
      {code + "CMakeLists.txt", templates::fill(templates::kExpertCMakeLists, values)},
      {code + "main.cpp", templates::fill(templates::kMain, values)},
      {code + spec.name + "_expert.hpp", templates::fill(templates::kHeader, values)},
      {code + spec.name + "_expert.cpp", templates::fill(templates::kSource, values)},
      {tests + "CMakeLists.txt", templates::fill(templates::kTestCMakeLists, values)},
      {tests + "test_" + spec.name + "_expert.cpp", templates::fill(templates::kTest, values)}};
  for (const auto& channel : spec.new_channels)
    files.push_back({"lcmtypes/" + channel.type + ".lcm",
                     templates::fill(templates::kMessageType,
                                     {{"name", spec.name}, {"channel", channel.name}, {"type", channel.type}})});
  return files;
}

namespace {

constexpr const char* kStaging = ".beft-new-expert-staging";
constexpr const char* kSteps = ".steps";
constexpr const char* kComplete = ".complete";

void writeText(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Moves every staged file whose place is still free into it, then removes
// the staging folder.
void moveStagedFiles(const fs::path& root, const fs::path& staging) {
  for (const auto& entry : fs::recursive_directory_iterator(staging)) {
    const fs::path relative = fs::relative(entry.path(), staging);
    if (!entry.is_regular_file() || relative == kSteps || relative == kComplete) continue;
    const fs::path target = root / relative;
    if (fs::exists(target)) continue;  // moved before the kill
    fs::create_directories(target.parent_path());
    fs::rename(entry.path(), target);
  }
  fs::remove_all(staging);
}

}  // namespace

void writeFiles(const std::string& root, const std::vector<GeneratedFile>& files, const std::string& steps) {
  for (const auto& file : files)
    if (fs::exists(fs::path(root) / file.path)) throw SpecError(file.path + " exists: nothing written");
  const fs::path staging = fs::path(root) / kStaging;
  fs::remove_all(staging);
  for (const auto& file : files) writeText(staging / file.path, file.text);
  writeText(staging / kSteps, steps);
  writeText(staging / (std::string(kComplete) + ".new"), "");
  fs::rename(staging / (std::string(kComplete) + ".new"), staging / kComplete);  // all staged, at once
  moveStagedFiles(root, staging);
}

std::optional<std::string> finishInterruptedWrite(const std::string& root) {
  const fs::path staging = fs::path(root) / kStaging;
  if (!fs::exists(staging)) return std::nullopt;
  if (!fs::exists(staging / kComplete)) {
    fs::remove_all(staging);
    return std::nullopt;
  }
  const std::string steps = readText(staging / kSteps);
  moveStagedFiles(root, staging);
  return steps;
}

}  // namespace beft::new_expert

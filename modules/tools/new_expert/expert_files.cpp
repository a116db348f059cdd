#include "tools/new_expert/expert_files.hpp"

#include <filesystem>
#include <fstream>

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

void writeFiles(const std::string& root, const std::vector<GeneratedFile>& files) {
  for (const auto& file : files)
    if (fs::exists(fs::path(root) / file.path)) throw SpecError(file.path + " exists: nothing written");
  for (const auto& file : files) {
    const fs::path path = fs::path(root) / file.path;
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary);
    out << file.text;
    if (!out) throw std::runtime_error("cannot write " + path.string());
  }
}

}  // namespace beft::new_expert

#include "tools/experiment/scenes.hpp"

#include <filesystem>
#include <fstream>

#include "tools/experiment/child_process.hpp"

namespace beft::experiment {
namespace fs = std::filesystem;

std::string lastLineOf(const std::string& file, const std::string& containing) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos && line.find(containing) != std::string::npos)
      last = line;
  return last;
}

namespace {

// beft-generate writes the file whole or not at all (beside it first, then
// renamed), so an interrupted generation is never taken for a scene.
void generate(const Scene& scene, const std::string& bin_dir) {
  const Generation& g = *scene.generation;
  const std::string output = fs::path(scene.file).replace_extension(".generate.txt").string();
  const int code = runProgram({bin_dir + "/beft-generate", g.kind, "--size", std::to_string(g.width),
                               std::to_string(g.height), "--objects", std::to_string(g.objects), "--seed",
                               std::to_string(g.seed), "--out", scene.file},
                              output);
  if (code != 0)
    throw ExperimentError("cannot generate scene " + scene.name + ": " + lastLineOf(output) + " (exit code " +
                          std::to_string(code) + ")");
}

}  // namespace

void generateScenes(Experiment& experiment, const std::string& out_dir, const std::string& bin_dir,
                    const std::function<void(const std::string&)>& say) {
  const fs::path folder = fs::path(out_dir) / "scenes";
  for (auto& scene : experiment.scenes) {
    if (!scene.generation) continue;
    scene.file = (folder / (scene.name + ".xml")).string();
    if (fs::exists(scene.file)) continue;
    fs::create_directories(folder);
    say("generating scene " + scene.name);
    generate(scene, bin_dir);
  }
}

}  // namespace beft::experiment

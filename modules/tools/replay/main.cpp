// beft-replay: offline tools over a recorded run (./beft replay LOG ...).
//   --module NAME : re-run one expert's real binary against the log, compare outputs
//   --to DIR|MP4  : render the run frame by frame (beft-render)
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <filesystem>
#include <map>

#include "lib/common/command_line.hpp"
#include "lib/common/own_bin_dir.hpp"
#include "lib/launch/run_parameters.hpp"

namespace {
int execProgram(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (auto& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  std::fprintf(stderr, "[replay] error: cannot execute %s (is it built? ./beft build)\n", argv[0]);
  return 1;
}

struct Options {
  std::string log, module, to;
  std::vector<std::string> params;
  std::string every, fps;  // passed on to beft-render as given
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Offline tools over a recorded run; the live system is never needed.\n"
      "  --module NAME: runs that expert's own program with --replay LOG and the parameters it ran with "
      "(parameters.json beside the log, written by ./beft run; --param overrides them): feeds it the inputs it "
      "read during the run, in order, fires it at every FIRE it got, and compares what it writes "
      "with what it wrote then (exact in lockstep runs). Prints how many outputs match and the "
      "first difference with both values. Exit 0 on an exact match, 3 on differences, 4 when the log "
      "lacks inputs the expert needs (the camera frames of a run recorded with --record-camera every:N "
      "or none): then it says which instead of listing differences.\n"
      "  --to DIR|FILE.mp4: renders the run frame by frame (top-down view and camera image).",
      "beft-replay");
  app.add_option("log", o.log, "the run's LCM log (logs/<run>/run.lcmlog)")->required()->check(CLI::ExistingFile);
  auto* module_option = app.add_option("--module", o.module,
      "expert to replay: world, ears, geometry, vision, audio, visual_labels, acoustic_labels, fusion, dw, exploration, tasks");
  app.add_option("--param", o.params, "NAME=VALUE for the replayed expert (repeatable)")->needs(module_option);
  auto* to_option = app.add_option("--to", o.to, "render into this folder of PNGs, or this .mp4 file");
  module_option->excludes(to_option);
  app.add_option("--every", o.every, "with --to: render every N-th tick (default 5)")->needs(to_option);
  app.add_option("--fps", o.fps, "with --to and a video: frame rate (default 10)")->needs(to_option);
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

// Runs the expert's own program with --replay, or beft-render.
int replay(const Options& o) {
  const std::string bin = beft::ownBinDir();
  if (!o.module.empty()) {
    std::string program = o.module;
    std::replace(program.begin(), program.end(), '_', '-');
    std::vector<std::string> args = {bin + "/beft-" + program, "--replay", o.log, "--name", o.module};
    const std::string recorded =
        (std::filesystem::path(o.log).parent_path() / beft::launch::kRunParametersFile).string();
    std::map<std::string, std::string> parameters;
    try {
      parameters = beft::launch::readRunParameters(recorded, o.module);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "[replay] error: %s\n", e.what());
      return 2;
    }
    for (const auto& p : o.params) {
      const auto eq = p.find('=');
      if (eq == std::string::npos || eq == 0) {
        std::fprintf(stderr, "[replay] error: --param '%s' is not NAME=VALUE\n", p.c_str());
        return 2;
      }
      parameters[p.substr(0, eq)] = p.substr(eq + 1);
    }
    std::string said;
    for (const auto& [name, value] : parameters) {
      args.insert(args.end(), {"--param", name + "=" + value});
      said += " " + name + "=" + value;
    }
    if (!said.empty()) std::fprintf(stderr, "[replay] %s with%s\n", o.module.c_str(), said.c_str());
    return execProgram(args);
  }
  if (!o.to.empty()) {
    std::vector<std::string> args = {bin + "/beft-render", o.log, "--to", o.to};
    if (!o.every.empty()) args.insert(args.end(), {"--every", o.every});
    if (!o.fps.empty()) args.insert(args.end(), {"--fps", o.fps});
    return execProgram(args);
  }
  std::fprintf(stderr, "[replay] error: say what to do: --module NAME or --to DIR|FILE.mp4 (see --help)\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return replay(options);
}

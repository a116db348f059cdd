// beft-replay: offline tools over a recorded run (./beft replay LOG ...).
//   --module NAME : re-run one expert's real binary against the log, compare outputs
//   --to DIR|MP4  : render the run frame by frame (beft-render)
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdio>

#include "own_bin_dir.hpp"

namespace {
int execProgram(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (auto& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  std::fprintf(stderr, "[replay] error: cannot execute %s (is it built? ./beft build)\n", argv[0]);
  return 1;
}
}  // namespace

int main(int argc, char** argv) {
  std::string log, module, to;
  std::vector<std::string> params;
  CLI::App app(
      "Offline tools over a recorded run; the live system is never needed.\n"
      "  --module NAME: runs that expert's own program with --replay LOG: feeds it the inputs it "
      "read during the run, in order, fires it at every FIRE it got, and compares what it writes "
      "with what it wrote then (exact in lockstep runs). Prints how many outputs match and the "
      "first difference with both values. Exit 0 on an exact match, 3 on differences.\n"
      "  --to DIR|FILE.mp4: renders the run frame by frame (top-down view and camera image).",
      "beft-replay");
  app.add_option("log", log, "the run's LCM log (logs/<run>/run.lcmlog)")->required()->check(CLI::ExistingFile);
  auto* module_option = app.add_option("--module", module,
      "expert to replay: world, geometry, vision, audio, visual_labels, acoustic_labels, fusion, dw, exploration, tasks");
  app.add_option("--param", params, "NAME=VALUE for the replayed expert (repeatable)")->needs(module_option);
  auto* to_option = app.add_option("--to", to, "render into this folder of PNGs, or this .mp4 file");
  module_option->excludes(to_option);
  std::string every, fps;
  app.add_option("--every", every, "with --to: render every N-th tick (default 5)")->needs(to_option);
  app.add_option("--fps", fps, "with --to and a video: frame rate (default 10)")->needs(to_option);
  CLI11_PARSE(app, argc, argv);

  const std::string bin = beft::ownBinDir();
  if (!module.empty()) {
    std::string program = module;
    std::replace(program.begin(), program.end(), '_', '-');
    std::vector<std::string> args = {bin + "/beft-" + program, "--replay", log, "--name", module};
    for (const auto& p : params) {
      args.push_back("--param");
      args.push_back(p);
    }
    return execProgram(args);
  }
  if (!to.empty()) {
    std::vector<std::string> args = {bin + "/beft-render", log, "--to", to};
    if (!every.empty()) args.insert(args.end(), {"--every", every});
    if (!fps.empty()) args.insert(args.end(), {"--fps", fps});
    return execProgram(args);
  }
  std::fprintf(stderr, "[replay] error: say what to do: --module NAME or --to DIR|FILE.mp4 (see --help)\n");
  return 2;
}

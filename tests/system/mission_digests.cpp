// mission_digests: the pins of the mission digest test, from runs of this
// build, for a person to review and paste in (see tests/system/README.md).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <CLI/CLI.hpp>

#include "lib/common/command_line.hpp"
#include "tests/system/run_digests.hpp"
#include "tests/system/run_support.hpp"

using namespace beft::system_test;

namespace {

// The digests of one scenario's run, recorded as the mission test records it.
RunDigests digestsOfARun(const std::string& scenario) {
  const std::string dir = makeTempDir("pin_" + scenario);
  const auto run = runCommand(binDir() + "/beft-run " + sourceDir() + "/scenarios/" + scenario +
                                  ".xml --no-report --out " + dir, 600);
  if (run.exit_code != 0) throw std::runtime_error(scenario + ": beft-run exited with " +
                                                   std::to_string(run.exit_code) + ":\n" + run.output);
  RunDigests digests = digestRun(readLog(dir + "/run.lcmlog"));
  std::filesystem::remove_all(dir);
  return digests;
}

}  // namespace

int main(int argc, char** argv) {
  std::string fingerprints_path;
  CLI::App app{"mission_digests: runs yard, peek and decoy with this build and prints on stdout the content of "
               "tests/system/data/data_digests.json for them (the pins of MissionDigests in test_mission). "
               "Review the change before pasting it in; a commit that re-pins says why its messages changed.",
               "mission_digests"};
  app.add_option("--fingerprints", fingerprints_path,
                 "also write the per-message fingerprints (tests/system/data/message_fingerprints.json) here");
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return *code;
  nlohmann::json pins = nlohmann::json::object(), fingerprints = nlohmann::json::object();
  try {
    for (const std::string scenario : {"decoy", "peek", "yard"}) {
      const RunDigests digests = digestsOfARun(scenario);
      pins[scenario] = digestsAsJson(digests);
      fingerprints[scenario] = fingerprintsAsJson(digests);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mission_digests: %s\n", e.what());
    return 1;
  }
  std::printf("%s\n", pins.dump(2).c_str());
  if (!fingerprints_path.empty() && !(std::ofstream(fingerprints_path) << fingerprints.dump(1) << "\n")) {
    std::fprintf(stderr, "mission_digests: cannot write %s\n", fingerprints_path.c_str());
    return 1;
  }
  return 0;
}

// beft-check: validates a scenario file before anything runs. Prints
// FILE:LINE: message and exits 1 on the first problem; prints a summary on
// success.
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "lib/common/command_line.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "tools/check/scenario_summary.hpp"

namespace {

struct Options {
  std::string path;
  bool quiet = false, strict = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Validate a scenario XML file (scenario-format.md) and print a summary.\n"
      "On error prints FILE:LINE: message on stderr and exits 1. Warnings\n"
      "(unknown elements or attributes, ...) go to stderr as FILE:LINE: warning: ...");
  app.add_option("file", o.path, "scenario XML file")->required();
  app.add_flag("-q,--quiet", o.quiet, "print nothing on success, only problems");
  app.add_flag("--strict", o.strict, "treat warnings as errors (exit 1 if there are any)");
  // --help exits 0; a usage error exits 2, apart from a refused scenario (1).
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return *code == 0 ? 0 : 2;
  return std::nullopt;
}

int check(const Options& o) {
  try {
    const beft::scenario::Scenario scenario = beft::scenario::loadScenario(o.path);
    if (!o.quiet) beft::scenario::printSummary(scenario, std::cout);
    if (o.strict && !scenario.warnings.empty()) {
      std::cerr << o.path << ": " << scenario.warnings.size() << " warning(s), refused by --strict\n";
      return 1;
    }
    return 0;
  } catch (const beft::scenario::ScenarioError& error) {
    std::cerr << error.what() << "\n";
  } catch (const std::exception& error) {
    std::cerr << o.path << ": " << error.what() << "\n";
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return check(options);
}

// beft-check: validates a scenario file before anything runs. Prints
// FILE:LINE: message and exits 1 on the first problem; prints a summary on
// success.
#include <iostream>

#include <CLI/CLI.hpp>

#include "load_scenario.hpp"
#include "scenario_summary.hpp"

int main(int argc, char** argv) {
  CLI::App app(
      "Validate a scenario XML file (scenario-format.md) and print a summary.\n"
      "On error prints FILE:LINE: message on stderr and exits 1. Warnings\n"
      "(unknown elements or attributes, ...) go to stderr as FILE:LINE: warning: ...");
  std::string path;
  bool quiet = false;
  bool strict = false;
  app.add_option("file", path, "scenario XML file")->required();
  app.add_flag("-q,--quiet", quiet, "print nothing on success, only problems");
  app.add_flag("--strict", strict, "treat warnings as errors (exit 1 if there are any)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help exits 0; a usage error exits 2, apart from a refused scenario (1).
    return app.exit(error) == 0 ? 0 : 2;
  }

  try {
    const beft::scenario::Scenario scenario = beft::scenario::loadScenario(path);
    if (!quiet) beft::scenario::printSummary(scenario, std::cout);
    if (strict && !scenario.warnings.empty()) {
      std::cerr << path << ": " << scenario.warnings.size() << " warning(s), refused by --strict\n";
      return 1;
    }
    return 0;
  } catch (const beft::scenario::ScenarioError& error) {
    std::cerr << error.what() << "\n";
  } catch (const std::exception& error) {
    std::cerr << path << ": " << error.what() << "\n";
  }
  return 1;
}

// The one way every program ends its command-line parsing.
#pragma once

#include <optional>

#include <CLI/CLI.hpp>

namespace beft {

// Parses argv into `app`; an exit code when the program should end here
// (0 after --help, CLI11's code and message for a bad command line).
inline std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  return std::nullopt;
}

}  // namespace beft

// Loads and validates a scenario XML file (spec: scenario-format.md).
#pragma once

#include <ostream>
#include <string>

#include "lib/scenario/scenario.hpp"

namespace beft::scenario {

// Reads the file, fills every default, resolves sound paths relative to the
// file, sorts events by time (stably) and checks everything the format asks
// for. Throws ScenarioError ("FILE:LINE: message") on the first problem.
// Warnings (unknown elements or attributes, events after the end, ...) are
// kept in Scenario::warnings and also written to stderr.
Scenario loadScenario(const std::string& path);

// The same, writing warnings to `warnings` instead (nullptr: keep them only
// in Scenario::warnings).
Scenario loadScenario(const std::string& path, std::ostream* warnings);

// The congruency table the format defines when a file gives none.
std::map<std::pair<std::string, std::string>, double> defaultCongruency();

// The categories the format defines when a file gives none.
std::vector<std::string> defaultCategories();

}  // namespace beft::scenario

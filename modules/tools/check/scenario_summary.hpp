// A one-screen, human-readable summary of a loaded scenario.
#pragma once

#include <ostream>

#include "lib/scenario/scenario.hpp"

namespace beft::scenario {

// Name, world, timing, robot, objects by category, sound sources (with their
// WAV durations), paths, events in time order and the congruency table.
void printSummary(const Scenario& scenario, std::ostream& out);

}  // namespace beft::scenario

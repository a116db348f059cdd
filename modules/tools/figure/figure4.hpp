// The paper's Fig. 4: the weights plot of a fresh fig4_dw run (every
// process of the mission, started and stopped by beft-run).
#pragma once

#include <string>

namespace beft::figure {

// Runs `run_program` on the scenario into a scratch folder and copies its
// weights.png to `out`; throws std::runtime_error with the run's own words.
void drawFigure4(const std::string& run_program, const std::string& scenario_path, const std::string& out);

}  // namespace beft::figure

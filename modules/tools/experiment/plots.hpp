// The experiment's pictures: success.png (each condition's success rate with
// its 95 % Wilson interval) and time_to_find.png (per condition, the share of
// the persons present found by each simulated time, over its done episodes).
#pragma once

#include <string>
#include <vector>

#include "tools/experiment/summary.hpp"

namespace beft::experiment {

// False if a picture could not be written.
bool writeSuccessPlot(const Summary& summary, const std::string& file);
bool writeTimeToFindPlot(const std::vector<EpisodeResult>& results, const std::string& file);

}  // namespace beft::experiment

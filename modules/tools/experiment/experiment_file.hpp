// Reads an experiment file (the format: modules/tools/README.md, "Experiments").
// Everything wrong is refused with FILE:LINE: unknown elements and attributes,
// bad numbers, empty factors, missing files, duplicate values.
#pragma once

#include <string>

#include "tools/experiment/experiment.hpp"

namespace beft::experiment {

// Throws ExperimentError("FILE:LINE: what is wrong").
Experiment readExperiment(const std::string& path);

}  // namespace beft::experiment

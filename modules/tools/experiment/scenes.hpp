// The generated scenes of an experiment, written once into OUT/scenes/ by
// beft-generate and found there again when the experiment is resumed.
#pragma once

#include <functional>
#include <string>

#include "tools/experiment/experiment.hpp"

namespace beft::experiment {

// Fills in every generated scene's file, generating those not yet there.
// Throws ExperimentError when beft-generate fails (its last line said).
void generateScenes(Experiment& experiment, const std::string& out_dir, const std::string& bin_dir,
                    const std::function<void(const std::string&)>& say);

// The last line of a text file that is not empty ("" if none).
std::string lastLineOf(const std::string& file, const std::string& containing = "");

}  // namespace beft::experiment

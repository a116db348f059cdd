// The episodes of an experiment: the product of its scenes and factors, each
// with an id made from its values, so that the same experiment file gives the
// same ids (the folders a resumed experiment finds again).
#pragma once

#include <string>
#include <vector>

#include "tools/experiment/experiment.hpp"

namespace beft::experiment {

// Scene outermost, then the factors in the order declared, the last fastest;
// or the experiment's <episode> list, in its order.
// Throws ExperimentError if two episodes would get the same id.
std::vector<Episode> expandEpisodes(const Experiment& experiment);

// "planner-astar", "seed-3", "dw_alpha-0.2", a scene's bare name: one piece of an id.
std::string idPart(const std::string& factor, const std::string& value);

}  // namespace beft::experiment

// A Petri net as a Graphviz graph: places as circles with their tokens,
// transitions as boxes with the expert they fire (silent ones as bars, the
// tick doubled), arcs with their weight when above 1. Every node carries an
// id and a class that Graphviz's SVG keeps ("place:ID" / class "place";
// "transition:ID" / class "transition expert-NAME"), so that a page can
// light a drawn net's marking without laying it out again.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lib/petri/petri_net.hpp"

namespace beft::arbiter {

// A marking to draw instead of the initial one, e.g. a run's last MARKING.
struct ShownMarking {
  std::map<std::string, int> tokens;  // place id -> tokens; places not listed hold none
  std::vector<std::string> running;   // experts firing at that moment
  std::string caption;                // "run 5cb3..., tick 299, step 3000: done tasks"
};

std::string netToDot(const Net& net, const std::optional<ShownMarking>& marking);

}  // namespace beft::arbiter

// Where a new expert goes in a schedule (a PNML net): in series right after
// an existing expert of its level (the model), so it fires in the same tick
// after the model and before whatever the model fed. That is a refinement of
// the model's transition: a safe, live net stays so. The edit is: a place
// and a transition (the model's, renamed, with its firing policy) after the
// model's transition, the model's outgoing arcs leaving the new transition
// instead, and two arcs model -> place -> new transition.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "tools/new_expert/expert_spec.hpp"

namespace beft::new_expert {

struct ArcChange {
  int line = 0;        // 1-based line of the arc in the file
  std::string before;  // the arc element as written
  std::string after;   // the same with source="t_NAME"
};

struct NetEdit {
  std::string model_expert;      // "" when the net has no expert of the level
  std::string model_transition;  // "t_dw"
  int model_end_line = 0;        // line of the model transition's </transition>
  std::size_t model_end = 0;     // offset just after it
  std::string nodes;             // place + transition to insert there (indented)
  std::vector<ArcChange> arc_changes;
  int last_arc_line = 0;
  std::size_t last_arc_end = 0;  // offset just after the last <arc .../>
  std::string new_arcs;          // the two arcs to insert there (indented)
};

// The edit of one net's text (read from `file` for messages); throws
// SpecError if the net cannot be read.
NetEdit planNetEdit(const std::string& text, const std::string& file, const ExpertSpec& spec);
// The text with the edit made (for checking what the steps would give).
std::string applyNetEdit(const std::string& text, const NetEdit& edit);
// The steps for every net in source_root/scenarios/nets/, in name order.
std::string netSteps(const ExpertSpec& spec);

}  // namespace beft::new_expert

// Graphviz's dot, run on a graph: the net tools' and the viewer's drawings
// of a net come from the same layout.
#pragma once

#include <string>

namespace beft::arbiter {

// Runs `dot -T<format>` on `graph` and writes the drawing to `out_path`.
// Returns "" on success, else what went wrong (dot missing or failing).
std::string runGraphviz(const std::string& graph, const std::string& format, const std::string& out_path);

// The drawing itself (`format` as dot takes it: "svg"); "" with `why` set
// when dot could not draw it.
std::string drawWithGraphviz(const std::string& graph, const std::string& format, std::string& why);

}  // namespace beft::arbiter

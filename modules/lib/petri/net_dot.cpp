#include "lib/petri/net_dot.hpp"

#include <algorithm>
#include <sstream>

namespace beft::arbiter {

namespace {

// A DOT string literal: quotes and backslashes escaped, line breaks kept as \n.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

// Up to four tokens as dots, more as a number.
std::string tokenText(int tokens) {
  if (tokens <= 0) return "";
  if (tokens <= 4) {
    std::string dots;
    for (int i = 0; i < tokens; ++i) dots += "\u25CF";
    return dots;
  }
  return std::to_string(tokens);
}

std::string label(const std::string& id, const std::string& name) {
  return name.empty() || name == id ? id : name + " (" + id + ")";
}

}  // namespace

std::string netToDot(const Net& net, const std::optional<ShownMarking>& marking) {
  std::ostringstream dot;
  dot << "digraph " << quoted(net.id.empty() ? "net" : net.id) << " {\n";
  dot << "  rankdir=LR;\n  node [fontname=\"Helvetica\", fontsize=10];\n  edge [arrowsize=0.7];\n";
  std::string title = label(net.id, net.name);
  if (marking) title += "\n" + marking->caption;
  dot << "  label=" << quoted(title) << "; labelloc=t;\n";
  for (size_t p = 0; p < net.places.size(); ++p) {
    const Place& place = net.places[p];
    int tokens = place.initial_tokens;
    if (marking) {
      const auto found = marking->tokens.find(place.id);
      tokens = found == marking->tokens.end() ? 0 : found->second;
    }
    const std::string dots = tokenText(tokens);
    dot << "  p" << p << " [shape=circle, width=0.45, fixedsize=true, label=" << quoted(dots)
        << ", xlabel=" << quoted(label(place.id, place.name)) << (tokens > 0 ? ", penwidth=2" : "")
        << ", id=" << quoted("place:" + place.id) << ", class=\"place\"];\n";
  }
  for (size_t t = 0; t < net.transitions.size(); ++t) {
    const Transition& transition = net.transitions[t];
    const bool running = marking && !transition.silent() &&
                         std::find(marking->running.begin(), marking->running.end(), transition.expert) !=
                             marking->running.end();
    dot << "  t" << t;
    const std::string node_names = ", id=" + quoted("transition:" + transition.id) + ", class=" +
                                   quoted(transition.expert.empty() ? "transition" : "transition expert-" + transition.expert);
    if (transition.silent() && !transition.is_tick && net.annotated) {
      dot << " [shape=box, style=filled, fillcolor=black, height=0.08, width=0.5, label=\"\", xlabel="
          << quoted(transition.id) << node_names << "];\n";
      continue;
    }
    std::string text = label(transition.id, transition.name);
    if (!transition.expert.empty()) text += "\n" + transition.expert;
    if (transition.is_tick) text += "\ntick";
    dot << " [shape=box, label=" << quoted(text) << (transition.is_tick ? ", peripheries=2" : "")
        << (running ? ", style=filled, fillcolor=\"#ffd54f\"" : "") << node_names << "];\n";
  }
  for (size_t t = 0; t < net.transitions.size(); ++t) {
    for (const auto& arc : net.transitions[t].inputs)
      dot << "  p" << arc.place << " -> t" << t << (arc.weight > 1 ? " [label=\"" + std::to_string(arc.weight) + "\"]" : "")
          << ";\n";
    for (const auto& arc : net.transitions[t].outputs)
      dot << "  t" << t << " -> p" << arc.place << (arc.weight > 1 ? " [label=\"" + std::to_string(arc.weight) + "\"]" : "")
          << ";\n";
  }
  dot << "}\n";
  return dot.str();
}

}  // namespace beft::arbiter

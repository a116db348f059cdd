#include "tools/new_expert/net_steps.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

#include "lib/petri/pnml_reader.hpp"

namespace beft::new_expert {

namespace fs = std::filesystem;

namespace {

int lineAt(const std::string& text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(offset), '\n'));
}

std::string indentAt(const std::string& text, std::size_t offset) {
  const std::size_t line_start = text.rfind('\n', offset) + 1;  // npos + 1 == 0
  return text.substr(line_start, offset - line_start);
}

// The model: the level's usual expert (or --after) if the net has it, else
// the net's last expert of the level; -1 if it has none.
int modelTransition(const arbiter::Net& net, const ExpertSpec& spec) {
  int last_of_level = -1;
  for (std::size_t i = 0; i < net.transitions.size(); ++i) {
    if (net.transitions[i].expert == spec.after) return static_cast<int>(i);
    if (!net.transitions[i].silent() && net.transitions[i].level == spec.level) last_of_level = static_cast<int>(i);
  }
  return last_of_level;
}

// The model's transition element renamed for the new expert, without its
// layout and comments.
std::string newTransition(const std::string& element, const std::string& model_id, const std::string& model_expert,
                          const std::string& name) {
  std::string text = std::regex_replace(element, std::regex("[ \t]*<!--[\\s\\S]*?-->[ \t]*\n?"), "");
  text = std::regex_replace(text, std::regex("[ \t]*<graphics>[\\s\\S]*?</graphics>[ \t]*\n?"), "");
  text = std::regex_replace(text, std::regex("id=\"" + model_id + "\""), "id=\"t_" + name + "\"");
  text = std::regex_replace(text, std::regex("<expert>" + model_expert + "</expert>"), "<expert>" + name + "</expert>");
  return std::regex_replace(text, std::regex("<name>\\s*<text>[^<]*</text>\\s*</name>"),
                            "<name><text>" + name + "</text></name>");
}

void planArcs(const std::string& text, const std::string& model_id, const std::string& name, NetEdit& edit) {
  const std::regex arc("<arc\\b[^>]*/>");
  const std::regex from_model("\\bsource=\"" + model_id + "\"");
  std::string indent;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), arc); it != std::sregex_iterator(); ++it) {
    const auto offset = static_cast<std::size_t>(it->position());
    edit.last_arc_line = lineAt(text, offset);
    edit.last_arc_end = offset + it->str().size();
    indent = indentAt(text, offset);
    if (std::regex_search(it->str(), from_model))
      edit.arc_changes.push_back(
          {edit.last_arc_line, it->str(), std::regex_replace(it->str(), from_model, "source=\"t_" + name + "\"")});
  }
  edit.new_arcs = "\n" + indent + "<arc id=\"a_" + name + "_in\" source=\"" + model_id + "\" target=\"p_" + name +
                  "_in\"/>\n" + indent + "<arc id=\"a_" + name + "_fire\" source=\"p_" + name + "_in\" target=\"t_" +
                  name + "\"/>";
}

std::string printEdit(const std::string& file, const NetEdit& edit, const ExpertSpec& spec) {
  if (edit.model_expert.empty())
    return file + ": no " + spec.level + "-level expert in this net; " + spec.name +
           " does not fire under it unless you add it by hand.\n\n";
  // Bottom up, so the line numbers (of the file as it is) hold while editing.
  std::string text = file + ": after " + edit.model_expert + " (" + edit.model_transition + "), in series; from " +
                     "the bottom up, so the line numbers hold:\n";
  text += "  1. after line " + std::to_string(edit.last_arc_line) + " (the last arc), add:" + edit.new_arcs + "\n";
  text += "  2. make the arcs that leave " + edit.model_transition + " leave t_" + spec.name + ":\n";
  for (auto change = edit.arc_changes.rbegin(); change != edit.arc_changes.rend(); ++change)
    text += "       line " + std::to_string(change->line) + ": " + change->before + "\n       becomes: " +
            change->after + "\n";
  text += "  3. after line " + std::to_string(edit.model_end_line) + " (the </transition> of " +
          edit.model_transition + "), add:" + edit.nodes + "\n\n";
  return text;
}

}  // namespace

NetEdit planNetEdit(const std::string& text, const std::string& file, const ExpertSpec& spec) {
  arbiter::Net net;
  try {
    net = arbiter::readPnmlString(text, file);
  } catch (const arbiter::NetError& e) {
    throw SpecError(std::string("cannot read the net: ") + e.what());
  }
  NetEdit edit;
  const int model = modelTransition(net, spec);
  if (model < 0) return edit;
  edit.model_expert = net.transitions[model].expert;
  edit.model_transition = net.transitions[model].id;
  const std::size_t start = text.find("<transition id=\"" + edit.model_transition + "\"");
  const std::size_t end = text.find("</transition>", start);
  if (start == std::string::npos || end == std::string::npos)
    throw SpecError(file + ": transition " + edit.model_transition + " is not written <transition id=\"...\">");
  edit.model_end = end + std::string("</transition>").size();
  edit.model_end_line = lineAt(text, end);
  const std::string indent = indentAt(text, start);
  edit.nodes = "\n" + indent + "<place id=\"p_" + spec.name + "_in\"/>\n" + indent +
               newTransition(text.substr(start, edit.model_end - start), edit.model_transition, edit.model_expert,
                             spec.name);
  planArcs(text, edit.model_transition, spec.name, edit);
  return edit;
}

std::string applyNetEdit(const std::string& text, const NetEdit& edit) {
  if (edit.model_expert.empty()) return text;
  std::string out = text.substr(0, edit.model_end) + edit.nodes + text.substr(edit.model_end);
  const std::size_t shift = edit.nodes.size();
  const std::size_t arcs_end = edit.last_arc_end + shift;
  out = out.substr(0, arcs_end) + edit.new_arcs + out.substr(arcs_end);
  for (const auto& change : edit.arc_changes) {
    const std::size_t at = out.find(change.before);
    out.replace(at, change.before.size(), change.after);
  }
  return out;
}

std::string netSteps(const ExpertSpec& spec) {
  std::vector<fs::path> nets;
  for (const auto& entry : fs::directory_iterator(fs::path(spec.source_root) / "scenarios" / "nets"))
    if (entry.path().extension() == ".pnml") nets.push_back(entry.path());
  std::sort(nets.begin(), nets.end());
  std::string text;
  for (const auto& path : nets) {
    std::ifstream in(path, std::ios::binary);
    const std::string net((std::istreambuf_iterator<char>(in)), {});
    const std::string file = "scenarios/nets/" + path.filename().string();
    text += printEdit(file, planNetEdit(net, file, spec), spec);
  }
  return text;
}

}  // namespace beft::new_expert

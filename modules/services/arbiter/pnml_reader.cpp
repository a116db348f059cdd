#include "pnml_reader.hpp"

#include <sys/stat.h>
#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace beft::arbiter {

namespace {

using tinyxml2::XMLElement;

constexpr size_t kMaxProblems = 50;
constexpr const char* kToolName = "beft";
constexpr const char* kToolVersion = "1";

std::string joinLines(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& line : lines) {
    if (!text.empty()) text += '\n';
    text += line;
  }
  return text;
}

std::string trim(const char* text) {
  if (!text) return "";
  std::string s(text);
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

bool isName(const char* element_name, const char* expected) {
  return element_name && std::strcmp(element_name, expected) == 0;
}

bool validExpertName(const std::string& name) {
  if (name.empty()) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      return false;
  return true;
}

std::optional<long long> parseWholeNumber(const std::string& text) {
  if (text.empty()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (errno != 0 || end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

std::optional<double> parseSeconds(const std::string& text) {
  if (text.empty()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (errno != 0 || end != text.c_str() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// tinyxml2's message without its "Error=... ErrorID=... Line number=N" wrapper.
std::string xmlErrorText(const tinyxml2::XMLDocument& document) {
  if (document.ErrorID() == tinyxml2::XML_ERROR_EMPTY_DOCUMENT) return "the file is empty";
  std::string text = std::string("not well-formed XML (") + document.ErrorName();
  const std::string full = document.ErrorStr();
  const auto detail = full.find(": ", full.find("Line number="));
  if (detail != std::string::npos) text += ": " + full.substr(detail + 2);
  return text + ")";
}

// One node of the net as declared, before arcs are resolved.
enum class NodeKind { Place, Transition, Reference, Other };

struct DeclaredId {
  NodeKind kind = NodeKind::Other;
  int index = -1;          // into places or transitions
  std::string reference;   // for reference nodes: the id they stand for
  int line = 0;
};

struct PendingArc {
  std::string id, source, target;
  int weight = 1;
  int line = 0;
};

class PnmlReader {
 public:
  explicit PnmlReader(std::string file) { net_.file = std::move(file); }

  Net read(tinyxml2::XMLDocument& document) {
    if (document.Error()) {
      problem(std::max(1, document.ErrorLineNum()), xmlErrorText(document));
      throw NetError(problems_);
    }
    const XMLElement* root = document.RootElement();
    if (!root || !isName(root->Name(), "pnml")) {
      problem(root ? root->GetLineNum() : 1,
              std::string("root element is <") + (root ? root->Name() : "") + ">, expected <pnml>");
      throw NetError(problems_);
    }
    const XMLElement* net_element = nullptr;
    int nets = 0;
    for (const XMLElement* e = root->FirstChildElement("net"); e; e = e->NextSiblingElement("net")) {
      if (++nets == 1) net_element = e;
      else problem(e->GetLineNum(), "second <net> in the file; the arbiter reads one net per file");
    }
    if (!net_element) {
      problem(root->GetLineNum(), "<pnml> holds no <net>");
      throw NetError(problems_);
    }
    readNet(*net_element);
    if (!problems_.empty()) throw NetError(problems_);
    return std::move(net_);
  }

 private:
  void problem(int line, const std::string& message) {
    if (problems_.size() < kMaxProblems)
      problems_.push_back(net_.file + ":" + std::to_string(line) + ": " + message);
    else if (problems_.size() == kMaxProblems)
      problems_.push_back(net_.file + ": more problems not shown");
  }

  void readNet(const XMLElement& net) {
    net_.id = trim(net.Attribute("id"));
    if (const char* type = net.Attribute("type")) {
      const std::string t = type;
      const std::string suffix = "ptnet";
      if (t.size() < suffix.size() || t.compare(t.size() - suffix.size(), suffix.size(), suffix) != 0)
        problem(net.GetLineNum(), "net type '" + t + "' is not a P/T net (.../grammar/ptnet expected)");
    }
    net_.name = labelText(net, "name").value_or("");
    readContainer(net);
    resolveArcs();
    checkStructure(net.GetLineNum());
  }

  // <net> and <page>: nodes may sit at any depth of pages.
  void readContainer(const XMLElement& container) {
    for (const XMLElement* e = container.FirstChildElement(); e; e = e->NextSiblingElement()) {
      const char* name = e->Name();
      if (isName(name, "page")) {
        declareId(*e, NodeKind::Other, -1);
        readContainer(*e);
      } else if (isName(name, "place")) {
        readPlace(*e);
      } else if (isName(name, "transition")) {
        readTransition(*e);
      } else if (isName(name, "arc")) {
        readArc(*e);
      } else if (isName(name, "referencePlace") || isName(name, "referenceTransition")) {
        const std::string id = declareId(*e, NodeKind::Reference, -1);
        const std::string ref = trim(e->Attribute("ref"));
        if (ref.empty()) problem(e->GetLineNum(), "<" + std::string(name) + "> without a ref attribute");
        if (!id.empty()) ids_[id].reference = ref;
      }
      // Everything else (graphics, names, other tools' data) does not change the net.
    }
  }

  // Registers the element's id; returns it, or "" when missing or a duplicate.
  std::string declareId(const XMLElement& e, NodeKind kind, int index) {
    const std::string id = trim(e.Attribute("id"));
    if (id.empty()) {
      problem(e.GetLineNum(), "<" + std::string(e.Name()) + "> without an id attribute");
      return "";
    }
    const auto found = ids_.find(id);
    if (found != ids_.end()) {
      problem(e.GetLineNum(), "duplicate id '" + id + "' (first used at line " +
                                  std::to_string(found->second.line) + ")");
      return "";
    }
    DeclaredId declared;
    declared.kind = kind;
    declared.index = index;
    declared.line = e.GetLineNum();
    ids_[id] = declared;
    return id;
  }

  // The text of a PNML label (<name>, <initialMarking>, <inscription>):
  // its <text> child, else its <value> child, else its own text.
  std::optional<std::string> labelText(const XMLElement& owner, const char* label,
                                       int* line = nullptr) {
    const XMLElement* element = owner.FirstChildElement(label);
    if (!element) return std::nullopt;
    if (line) *line = element->GetLineNum();
    if (const XMLElement* text = element->FirstChildElement("text")) {
      if (line) *line = text->GetLineNum();
      return trim(text->GetText());
    }
    if (const XMLElement* value = element->FirstChildElement("value")) {
      if (line) *line = value->GetLineNum();
      return trim(value->GetText());
    }
    return trim(element->GetText());
  }

  // The <toolspecific tool="beft"> element of a node, if any (one at most).
  const XMLElement* beftAnnotation(const XMLElement& owner, const std::string& owner_id) {
    const XMLElement* found = nullptr;
    for (const XMLElement* e = owner.FirstChildElement("toolspecific"); e;
         e = e->NextSiblingElement("toolspecific")) {
      if (trim(e->Attribute("tool")) != kToolName) continue;
      if (found) {
        problem(e->GetLineNum(), "second <toolspecific tool=\"beft\"> in '" + owner_id + "'");
        continue;
      }
      const char* version = e->Attribute("version");
      if (version && trim(version) != kToolVersion)
        problem(e->GetLineNum(), "<toolspecific tool=\"beft\"> version '" + trim(version) +
                                     "' is not supported (version \"1\" expected)");
      found = e;
    }
    return found;
  }

  void readPlace(const XMLElement& e) {
    Place place;
    place.line = e.GetLineNum();
    place.id = declareId(e, NodeKind::Place, static_cast<int>(net_.places.size()));
    if (place.id.empty()) return;
    place.name = labelText(e, "name").value_or("");
    int line = place.line;
    if (const auto text = labelText(e, "initialMarking", &line)) {
      const auto tokens = parseWholeNumber(*text);
      if (!tokens || *tokens < 0 || *tokens > 1000000)
        problem(line, "initial marking '" + *text + "' of place '" + place.id +
                          "' is not a whole number between 0 and 1000000");
      else
        place.initial_tokens = static_cast<int>(*tokens);
    }
    if (const XMLElement* annotation = beftAnnotation(e, place.id)) {
      for (const XMLElement* c = annotation->FirstChildElement(); c; c = c->NextSiblingElement())
        problem(c->GetLineNum(), "unknown element <" + std::string(c->Name()) +
                                     "> in <toolspecific tool=\"beft\"> of place '" + place.id +
                                     "' (places take no beft options)");
    }
    net_.places.push_back(std::move(place));
  }

  std::optional<ExpiryAction> parseAction(const XMLElement& e, const std::string& text,
                                          const std::string& transition_id, bool allow_retry) {
    if (text == "retry" && allow_retry) return ExpiryAction::Retry;
    if (text == "skip") return ExpiryAction::Skip;
    if (text == "fail") return ExpiryAction::Fail;
    problem(e.GetLineNum(), "<" + std::string(e.Name()) + "> of transition '" + transition_id +
                                "' is '" + text + "'; expected " +
                                (allow_retry ? "retry, skip or fail" : "skip or fail"));
    return std::nullopt;
  }

  std::optional<double> parsePositiveSeconds(const XMLElement& e, const std::string& text,
                                             const std::string& transition_id) {
    const auto seconds = parseSeconds(text);
    if (!seconds || *seconds <= 0.0 || *seconds > 86400.0) {
      problem(e.GetLineNum(), "<" + std::string(e.Name()) + "> of transition '" + transition_id +
                                  "' is '" + text + "'; expected seconds, > 0 and <= 86400");
      return std::nullopt;
    }
    return seconds;
  }

  void readTransition(const XMLElement& e) {
    Transition transition;
    transition.line = e.GetLineNum();
    transition.id = declareId(e, NodeKind::Transition, static_cast<int>(net_.transitions.size()));
    if (transition.id.empty()) return;
    transition.name = labelText(e, "name").value_or("");
    const std::string& id = transition.id;

    const XMLElement* annotation = beftAnnotation(e, id);
    if (!annotation) {
      problem(transition.line,
              "transition '" + id + "' names no expert: add <toolspecific tool=\"beft\" version=\"1\">"
              "<expert>NAME</expert></toolspecific>, or <silent/> there for a join or fork");
      net_.transitions.push_back(std::move(transition));
      return;
    }

    std::set<std::string> seen;
    std::optional<std::string> expert;
    bool marked_silent = false;
    bool has_policy = false;
    bool retries_given = false, after_retries_given = false;
    int policy_line = annotation->GetLineNum();
    FiringPolicy& policy = transition.policy;
    for (const XMLElement* c = annotation->FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string option = c->Name();
      const std::string text = trim(c->GetText());
      if (!seen.insert(option).second) {
        problem(c->GetLineNum(), "<" + option + "> given twice in transition '" + id + "'");
        continue;
      }
      if (option == "expert") {
        expert = text;
      } else if (option == "silent") {
        marked_silent = true;
      } else if (option == "tick") {
        transition.is_tick = true;
      } else if (option == "level") {
        transition.level = text;
      } else if (option == "timeout") {
        has_policy = true;
        policy_line = c->GetLineNum();
        if (auto s = parsePositiveSeconds(*c, text, id)) policy.timeout_s = *s;
      } else if (option == "heartbeat_timeout") {
        has_policy = true;
        policy_line = c->GetLineNum();
        if (auto s = parsePositiveSeconds(*c, text, id)) policy.heartbeat_timeout_s = *s;
      } else if (option == "on_timeout") {
        has_policy = true;
        policy_line = c->GetLineNum();
        if (auto a = parseAction(*c, text, id, true)) policy.on_timeout = *a;
      } else if (option == "on_failure") {
        has_policy = true;
        policy_line = c->GetLineNum();
        if (auto a = parseAction(*c, text, id, true)) policy.on_failure = *a;
      } else if (option == "retries") {
        has_policy = true;
        policy_line = c->GetLineNum();
        const auto n = parseWholeNumber(text);
        if (!n || *n < 0 || *n > 100) {
          problem(c->GetLineNum(), "<retries> of transition '" + id + "' is '" + text +
                                       "'; expected a whole number from 0 to 100");
        } else {
          policy.retries = static_cast<int>(*n);
          retries_given = true;
        }
      } else if (option == "after_retries") {
        has_policy = true;
        after_retries_given = true;
        policy_line = c->GetLineNum();
        if (auto a = parseAction(*c, text, id, false)) policy.after_retries = *a;
      } else {
        problem(c->GetLineNum(), "unknown element <" + option +
                                     "> in <toolspecific tool=\"beft\"> of transition '" + id +
                                     "' (known: expert silent tick level timeout heartbeat_timeout "
                                     "on_timeout on_failure retries after_retries)");
      }
    }

    if (expert && expert->empty()) expert.reset();
    if (expert && *expert == "-") {
      marked_silent = true;
      expert.reset();
    }
    const bool silent = marked_silent || transition.is_tick;
    if (expert && silent) {
      problem(annotation->GetLineNum(),
              "transition '" + id + "' names expert '" + *expert + "' but is marked " +
                  (transition.is_tick ? "<tick/> (the tick transition must be silent)" : "<silent/>"));
    } else if (expert && !validExpertName(*expert)) {
      problem(annotation->GetLineNum(), "expert name '" + *expert + "' of transition '" + id +
                                            "' must be letters, digits, '_', '-' or '.'");
    } else if (!expert && !silent) {
      problem(annotation->GetLineNum(),
              "transition '" + id + "' names no expert: add <expert>NAME</expert>, or <silent/> "
              "for a join or fork");
    }
    if (expert) transition.expert = *expert;

    if (silent && has_policy)
      problem(policy_line, "transition '" + id +
                               "' is silent: timeouts, retries and policies apply to experts only");
    const bool uses_retry = policy.on_timeout == ExpiryAction::Retry ||
                            policy.on_failure == ExpiryAction::Retry;
    if (uses_retry && !retries_given) policy.retries = 1;
    if (uses_retry && retries_given && policy.retries == 0)
      problem(policy_line, "transition '" + id + "' has a retry policy with <retries>0</retries>");
    if (!uses_retry && (retries_given || after_retries_given))
      problem(policy_line, "transition '" + id + "' gives <retries>/<after_retries> but neither "
                           "<on_timeout> nor <on_failure> is retry");
    net_.transitions.push_back(std::move(transition));
  }

  void readArc(const XMLElement& e) {
    PendingArc arc;
    arc.line = e.GetLineNum();
    arc.id = declareId(e, NodeKind::Other, -1);
    arc.source = trim(e.Attribute("source"));
    arc.target = trim(e.Attribute("target"));
    if (arc.source.empty() || arc.target.empty()) {
      problem(arc.line, "arc '" + arc.id + "' needs both a source and a target attribute");
      arcs_refused_ = true;
      return;
    }
    int line = arc.line;
    if (const auto text = labelText(e, "inscription", &line)) {
      const auto weight = parseWholeNumber(*text);
      if (!weight || *weight < 1 || *weight > 1000000) {
        problem(line, "weight '" + *text + "' of arc '" + arc.id +
                          "' is not a whole number between 1 and 1000000");
        arcs_refused_ = true;
        return;
      }
      arc.weight = static_cast<int>(*weight);
    }
    arcs_.push_back(arc);
  }

  // Follows reference nodes to the place or transition they stand for.
  const DeclaredId* resolve(const std::string& id, const PendingArc& arc, const char* end) {
    const DeclaredId* found = follow(id, arc, end);
    if (!found) arcs_refused_ = true;
    return found;
  }

  const DeclaredId* follow(const std::string& id, const PendingArc& arc, const char* end) {
    std::string current = id;
    for (int hops = 0; hops < 100; ++hops) {
      const auto found = ids_.find(current);
      if (found == ids_.end()) {
        problem(arc.line, "arc '" + arc.id + "': unknown " + end + " '" + current + "'");
        return nullptr;
      }
      if (found->second.kind == NodeKind::Reference) {
        current = found->second.reference;
        continue;
      }
      if (found->second.kind == NodeKind::Other) {
        problem(arc.line, "arc '" + arc.id + "': " + end + " '" + current +
                              "' is not a place or transition");
        return nullptr;
      }
      return &found->second;
    }
    problem(arc.line, "arc '" + arc.id + "': reference cycle through '" + id + "'");
    return nullptr;
  }

  void resolveArcs() {
    std::map<std::pair<std::string, std::string>, int> first_line;
    for (const auto& arc : arcs_) {
      const DeclaredId* source = resolve(arc.source, arc, "source");
      const DeclaredId* target = resolve(arc.target, arc, "target");
      if (!source || !target) continue;
      if (source->kind == target->kind) {
        arcs_refused_ = true;
        const char* kind = source->kind == NodeKind::Place ? "place" : "transition";
        problem(arc.line, "arc '" + arc.id + "' joins " + kind + " '" + arc.source + "' to " + kind +
                              " '" + arc.target + "'; an arc joins a place and a transition");
        continue;
      }
      const auto key = std::make_pair(arc.source, arc.target);
      if (const auto previous = first_line.find(key); previous != first_line.end()) {
        problem(arc.line, "second arc from '" + arc.source + "' to '" + arc.target +
                              "' (first at line " + std::to_string(previous->second) +
                              "); use one arc with a weight");
        continue;
      }
      first_line[key] = arc.line;
      if (source->kind == NodeKind::Place)
        net_.transitions[target->index].inputs.push_back({source->index, arc.weight});
      else
        net_.transitions[source->index].outputs.push_back({target->index, arc.weight});
    }
  }

  void checkStructure(int net_line) {
    if (net_.places.empty()) problem(net_line, "the net has no places");
    if (net_.transitions.empty()) problem(net_line, "the net has no transitions");
    std::vector<int> ticks;
    for (size_t i = 0; i < net_.transitions.size(); ++i) {
      const Transition& t = net_.transitions[i];
      if (t.is_tick) ticks.push_back(static_cast<int>(i));
      // A refused arc already explains a missing input.
      if (t.inputs.empty() && !arcs_refused_)
        problem(t.line, "transition '" + t.id + "' has no input place, so it would fire without end");
    }
    if (ticks.empty()) {
      problem(net_line, "no tick transition: mark the silent transition that closes a tick with "
                        "<toolspecific tool=\"beft\" version=\"1\"><tick/></toolspecific>");
    } else if (ticks.size() > 1) {
      for (size_t i = 1; i < ticks.size(); ++i)
        problem(net_.transitions[ticks[i]].line,
                "second tick transition '" + net_.transitions[ticks[i]].id + "' (first: '" +
                    net_.transitions[ticks[0]].id + "'); a net has exactly one");
    } else {
      net_.tick_transition = ticks[0];
    }
    std::vector<bool> connected(net_.places.size(), false);
    for (const auto& t : net_.transitions) {
      for (const auto& arc : t.inputs) connected[arc.place] = true;
      for (const auto& arc : t.outputs) connected[arc.place] = true;
    }
    for (size_t i = 0; i < net_.places.size(); ++i)
      if (!connected[i])
        net_.warnings.push_back(net_.file + ":" + std::to_string(net_.places[i].line) + ": place '" +
                                net_.places[i].id + "' has no arcs");
  }

  Net net_;
  std::vector<std::string> problems_;
  std::map<std::string, DeclaredId> ids_;
  std::vector<PendingArc> arcs_;
  bool arcs_refused_ = false;
};

}  // namespace

NetError::NetError(std::vector<std::string> problems)
    : std::runtime_error(joinLines(problems)), problems_(std::move(problems)) {}

Net readPnmlFile(const std::string& path) {
  struct stat info {};
  if (stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    throw NetError({path + ": is a directory, not a PNML file"});
  std::ifstream in(path, std::ios::binary);
  if (!in) throw NetError({path + ": cannot open the file: " + std::strerror(errno)});
  std::ostringstream text;
  text << in.rdbuf();
  return readPnmlString(text.str(), path);
}

Net readPnmlString(const std::string& text, const std::string& display_name) {
  tinyxml2::XMLDocument document;
  document.Parse(text.c_str(), text.size());
  PnmlReader reader(display_name);
  return reader.read(document);
}

}  // namespace beft::arbiter

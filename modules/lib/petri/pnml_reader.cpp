#include "lib/petri/pnml_reader.hpp"

#include "lib/petri/xml_encoding.hpp"

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

// The name without a namespace prefix ("pnml:place" -> "place").
const char* localName(const char* element_name) {
  if (!element_name) return "";
  const char* colon = std::strrchr(element_name, ':');
  return colon ? colon + 1 : element_name;
}

bool isName(const char* element_name, const char* expected) {
  return std::strcmp(localName(element_name), expected) == 0;
}

const XMLElement* firstChild(const XMLElement& parent, const char* name) {
  for (const XMLElement* e = parent.FirstChildElement(); e; e = e->NextSiblingElement())
    if (isName(e->Name(), name)) return e;
  return nullptr;
}

const XMLElement* nextSibling(const XMLElement& element, const char* name) {
  for (const XMLElement* e = element.NextSiblingElement(); e; e = e->NextSiblingElement())
    if (isName(e->Name(), name)) return e;
  return nullptr;
}

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Net types that are high-level nets, not place/transition nets.
bool isHighLevelType(const std::string& type) {
  const std::string t = lowercase(type);
  for (const char* kind : {"symmetricnet", "highlevelnet", "hlpng", "hlcorestructure", "coloured", "colored"})
    if (t.find(kind) != std::string::npos) return true;
  return false;
}

// TAPAAL's own file format looks like PNML but is not: its places carry the
// marking and invariant as attributes, arcs a time interval, and the file
// has shared places, constants and queries.
std::string tapaalNativeSign(const XMLElement& root) {
  for (const XMLElement* e = root.FirstChildElement(); e; e = e->NextSiblingElement()) {
    for (const char* own : {"shared-place", "shared-transition", "constant", "query", "k-bound", "feature"})
      if (isName(e->Name(), own)) return "<" + std::string(own) + ">";
    if (!isName(e->Name(), "net")) continue;
    for (const XMLElement* node = e->FirstChildElement(); node; node = node->NextSiblingElement()) {
      if (isName(node->Name(), "place") && (node->Attribute("initialMarking") || node->Attribute("invariant")))
        return "a place with an initialMarking or invariant attribute";
      if ((isName(node->Name(), "arc") || isName(node->Name(), "inputArc") || isName(node->Name(), "outputArc")) &&
          node->Attribute("inscription"))
        return "an arc with an inscription attribute";
    }
  }
  return "";
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

// A marking or weight as tools write it: "3", PIPE's "Default,3" (token
// class, count), or "" for none. Several classes with tokens: coloured.
struct TokenCount {
  std::optional<long long> value;
  bool coloured = false;
};

TokenCount parseTokenCount(const std::string& text) {
  TokenCount count;
  if (text.empty()) {
    count.value = 0;
    return count;
  }
  if (text.find(',') == std::string::npos) {
    count.value = parseWholeNumber(text);
    return count;
  }
  std::vector<std::string> fields;
  std::stringstream stream(text);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(trim(field.c_str()));
  if (fields.size() % 2 != 0) return count;
  long long total = 0;
  int classes_used = 0;
  for (size_t i = 0; i + 1 < fields.size(); i += 2) {
    const auto n = parseWholeNumber(fields[i + 1]);
    if (!n) return count;
    if (*n != 0) ++classes_used;
    total += *n;
  }
  count.coloured = classes_used > 1;
  count.value = total;
  return count;
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
  PnmlReader(std::string file, PnmlReadOptions options) : options_(std::move(options)) {
    net_.file = std::move(file);
  }

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
    if (const std::string sign = tapaalNativeSign(*root); !sign.empty()) {
      problem(root->GetLineNum(), "this is TAPAAL's own format (" + sign +
                                      "), not PNML: export the net from TAPAAL as PNML");
      throw NetError(problems_);
    }
    const XMLElement* net_element = chooseNet(*root);
    if (!net_element) throw NetError(problems_);
    readNet(*net_element);
    if (!problems_.empty()) throw NetError(problems_);
    return std::move(net_);
  }

 private:
  // The <net> asked for, or the first; several without a choice are noted.
  const XMLElement* chooseNet(const XMLElement& root) {
    std::vector<const XMLElement*> nets;
    for (const XMLElement* e = firstChild(root, "net"); e; e = nextSibling(*e, "net")) nets.push_back(e);
    if (nets.empty()) {
      problem(root.GetLineNum(), "<pnml> holds no <net>");
      return nullptr;
    }
    std::string ids;
    for (const XMLElement* e : nets) ids += (ids.empty() ? "'" : ", '") + trim(e->Attribute("id")) + "'";
    if (!options_.net_id.empty()) {
      for (const XMLElement* e : nets)
        if (trim(e->Attribute("id")) == options_.net_id) return e;
      problem(root.GetLineNum(), "no <net> with id '" + options_.net_id + "' (the file has " + ids + ")");
      return nullptr;
    }
    if (nets.size() > 1)
      net_.warnings.push_back(net_.file + ":" + std::to_string(nets[0]->GetLineNum()) + ": the file holds " +
                              std::to_string(nets.size()) + " nets (" + ids + "); reading the first, '" +
                              trim(nets[0]->Attribute("id")) + "' (choose one with --net-id)");
    return nets[0];
  }

  // What makes the net no arbiter schedule: an error for the arbiter, a
  // finding of its own when any P/T net is read.
  void scheduleProblem(int line, const std::string& message) {
    if (options_.schedule) problem(line, message);
    else net_.schedule_problems.push_back(net_.file + ":" + std::to_string(line) + ": " + message);
  }

  void problem(int line, const std::string& message) {
    if (problems_.size() < kMaxProblems)
      problems_.push_back(net_.file + ":" + std::to_string(line) + ": " + message);
    else if (problems_.size() == kMaxProblems)
      problems_.push_back(net_.file + ": more problems not shown");
  }

  void readNet(const XMLElement& net) {
    net_.id = trim(net.Attribute("id"));
    if (!checkNetType(net)) return;
    net_.name = labelText(net, "name").value_or("");
    readTokenClasses(net);
    readContainer(net);
    resolveArcs();
    checkStructure(net.GetLineNum());
  }

  // ISO P/T nets, ProM's and pm4py's core model, WoPeD's ptNetb and PIPE's
  // "P/T net" are read; high-level nets are refused; other types are read
  // as P/T nets with a warning.
  bool checkNetType(const XMLElement& net) {
    const std::string type = trim(net.Attribute("type"));
    if (type.empty()) return true;
    if (isHighLevelType(type)) {
      problem(net.GetLineNum(), "net type '" + type + "' is a high-level net, not a place/transition net "
                                "(.../grammar/ptnet expected)");
      return false;
    }
    const std::string t = lowercase(type);
    if (endsWith(t, "ptnet") || endsWith(t, "pnmlcoremodel") || endsWith(t, "ptnetb") || t == "p/t net")
      return true;
    net_.warnings.push_back(net_.file + ":" + std::to_string(net.GetLineNum()) + ": net type '" + type +
                            "' is not known; read as a place/transition net");
    return true;
  }

  // PIPE declares its token classes under <net>; more than one in use makes
  // a coloured net.
  void readTokenClasses(const XMLElement& net) {
    std::vector<std::string> enabled;
    for (const XMLElement* e = firstChild(net, "token"); e; e = nextSibling(*e, "token"))
      if (trim(e->Attribute("enabled")) != "false") enabled.push_back(trim(e->Attribute("id")));
    if (enabled.size() > 1) {
      std::string names;
      for (const auto& name : enabled) names += (names.empty() ? "" : ", ") + name;
      problem(net.GetLineNum(), "a coloured PIPE net (token classes " + names +
                                    "): only place/transition nets, with one kind of token, are read");
    }
  }

  // <net> and <page>: nodes may sit at any depth of pages.
  void readContainer(const XMLElement& container) {
    for (const XMLElement* e = container.FirstChildElement(); e; e = e->NextSiblingElement()) {
      const char* name = e->Name();
      if (isName(name, "page") && firstChild(*e, "net")) {
        // WoPeD keeps a subprocess as a page holding a <net> of its own,
        // with the id of the transition it refines: that transition stands
        // for it here.
        net_.warnings.push_back(net_.file + ":" + std::to_string(e->GetLineNum()) + ": WoPeD subprocess '" +
                                trim(e->Attribute("id")) + "' is read as its transition; its inner net is not expanded");
      } else if (isName(name, "page")) {
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
    const XMLElement* element = firstChild(owner, label);
    if (!element) return std::nullopt;
    if (line) *line = element->GetLineNum();
    if (const XMLElement* text = firstChild(*element, "text")) {
      if (line) *line = text->GetLineNum();
      return trim(text->GetText());
    }
    if (const XMLElement* value = firstChild(*element, "value")) {
      if (line) *line = value->GetLineNum();
      return trim(value->GetText());
    }
    return trim(element->GetText());
  }

  // The <toolspecific tool="beft"> element of a node, if any (one at most).
  const XMLElement* beftAnnotation(const XMLElement& owner, const std::string& owner_id) {
    const XMLElement* found = nullptr;
    for (const XMLElement* e = firstChild(owner, "toolspecific"); e; e = nextSibling(*e, "toolspecific")) {
      if (trim(e->Attribute("tool")) != kToolName) continue;
      net_.annotated = true;
      if (found) {
        scheduleProblem(e->GetLineNum(), "second <toolspecific tool=\"beft\"> in '" + owner_id + "'");
        continue;
      }
      const char* version = e->Attribute("version");
      if (version && trim(version) != kToolVersion)
        scheduleProblem(e->GetLineNum(), "<toolspecific tool=\"beft\"> version '" + trim(version) +
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
    if (const XMLElement* sort = firstChild(e, "hlinitialMarking") ? firstChild(e, "hlinitialMarking")
                                                                     : firstChild(e, "type"))
      problem(sort->GetLineNum(), "place '" + place.id + "' has a <" + localName(sort->Name()) +
                                      ">, which only high-level nets have; only place/transition nets are read");
    int line = place.line;
    if (const auto text = labelText(e, "initialMarking", &line)) {
      const TokenCount tokens = parseTokenCount(*text);
      if (tokens.coloured)
        problem(line, "initial marking '" + *text + "' of place '" + place.id +
                          "' holds tokens of several colours: a coloured net, not a place/transition net");
      else if (!tokens.value || *tokens.value < 0 || *tokens.value > 1000000)
        problem(line, "initial marking '" + *text + "' of place '" + place.id +
                          "' is not a whole number between 0 and 1000000");
      else
        place.initial_tokens = static_cast<int>(*tokens.value);
    }
    if (const XMLElement* annotation = beftAnnotation(e, place.id)) {
      for (const XMLElement* c = annotation->FirstChildElement(); c; c = c->NextSiblingElement())
        scheduleProblem(c->GetLineNum(), "unknown element <" + std::string(c->Name()) +
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
    scheduleProblem(e.GetLineNum(), "<" + std::string(e.Name()) + "> of transition '" + transition_id +
                                "' is '" + text + "'; expected " +
                                (allow_retry ? "retry, skip or fail" : "skip or fail"));
    return std::nullopt;
  }

  std::optional<double> parsePositiveSeconds(const XMLElement& e, const std::string& text,
                                             const std::string& transition_id) {
    const auto seconds = parseSeconds(text);
    if (!seconds || *seconds <= 0.0 || *seconds > 86400.0) {
      scheduleProblem(e.GetLineNum(), "<" + std::string(e.Name()) + "> of transition '" + transition_id +
                                  "' is '" + text + "'; expected seconds, > 0 and <= 86400");
      return std::nullopt;
    }
    return seconds;
  }

  // What a transition's <toolspecific tool="beft"> said besides its policy values.
  struct TransitionOptions {
    std::optional<std::string> expert;
    bool marked_silent = false;
    bool has_policy = false;
    bool retries_given = false, after_retries_given = false;
    int policy_line = 0;  // of the last policy option, else of the annotation
  };

  void readTransition(const XMLElement& e) {
    Transition transition;
    transition.line = e.GetLineNum();
    transition.id = declareId(e, NodeKind::Transition, static_cast<int>(net_.transitions.size()));
    if (transition.id.empty()) return;
    transition.name = labelText(e, "name").value_or("");

    const XMLElement* annotation = beftAnnotation(e, transition.id);
    if (!annotation) {
      scheduleProblem(transition.line,
              "transition '" + transition.id + "' names no expert: add <toolspecific tool=\"beft\" version=\"1\">"
              "<expert>NAME</expert></toolspecific>, or <silent/> there for a join or fork");
      net_.transitions.push_back(std::move(transition));
      return;
    }
    TransitionOptions options = readTransitionOptions(*annotation, transition);
    checkExpertAndSilence(*annotation, options, transition);
    checkPolicy(options, transition);
    net_.transitions.push_back(std::move(transition));
  }

  TransitionOptions readTransitionOptions(const XMLElement& annotation, Transition& transition) {
    TransitionOptions options;
    options.policy_line = annotation.GetLineNum();
    std::set<std::string> seen;
    for (const XMLElement* c = annotation.FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string option = localName(c->Name());
      const std::string text = trim(c->GetText());
      if (!seen.insert(option).second) {
        scheduleProblem(c->GetLineNum(), "<" + option + "> given twice in transition '" + transition.id + "'");
        continue;
      }
      if (option == "expert") {
        options.expert = text;
      } else if (option == "silent") {
        options.marked_silent = true;
      } else if (option == "tick") {
        transition.is_tick = true;
      } else if (option == "level") {
        transition.level = text;
      } else if (!readPolicyOption(*c, option, text, transition, options)) {
        scheduleProblem(c->GetLineNum(), "unknown element <" + option +
                                     "> in <toolspecific tool=\"beft\"> of transition '" + transition.id +
                                     "' (known: expert silent tick level timeout heartbeat_timeout "
                                     "on_timeout on_failure retries after_retries)");
      }
    }
    return options;
  }

  // One option of a transition's firing policy; false if `option` is none.
  bool readPolicyOption(const XMLElement& c, const std::string& option, const std::string& text,
                        Transition& transition, TransitionOptions& options) {
    const std::string& id = transition.id;
    FiringPolicy& policy = transition.policy;
    if (option == "timeout") {
      if (auto s = parsePositiveSeconds(c, text, id)) policy.timeout_s = *s;
    } else if (option == "heartbeat_timeout") {
      if (auto s = parsePositiveSeconds(c, text, id)) policy.heartbeat_timeout_s = *s;
    } else if (option == "on_timeout") {
      if (auto a = parseAction(c, text, id, true)) policy.on_timeout = *a;
    } else if (option == "on_failure") {
      if (auto a = parseAction(c, text, id, true)) policy.on_failure = *a;
    } else if (option == "retries") {
      const auto n = parseWholeNumber(text);
      if (!n || *n < 0 || *n > 100) {
        scheduleProblem(c.GetLineNum(), "<retries> of transition '" + id + "' is '" + text +
                                     "'; expected a whole number from 0 to 100");
      } else {
        policy.retries = static_cast<int>(*n);
        options.retries_given = true;
      }
    } else if (option == "after_retries") {
      options.after_retries_given = true;
      if (auto a = parseAction(c, text, id, false)) policy.after_retries = *a;
    } else {
      return false;
    }
    options.has_policy = true;
    options.policy_line = c.GetLineNum();
    return true;
  }

  // A transition names a valid expert or is silent (a join, a fork, the tick), never both.
  void checkExpertAndSilence(const XMLElement& annotation, TransitionOptions& options, Transition& transition) {
    const std::string& id = transition.id;
    std::optional<std::string>& expert = options.expert;
    if (expert && expert->empty()) expert.reset();
    if (expert && *expert == "-") {
      options.marked_silent = true;
      expert.reset();
    }
    const bool silent = options.marked_silent || transition.is_tick;
    if (expert && silent) {
      scheduleProblem(annotation.GetLineNum(),
              "transition '" + id + "' names expert '" + *expert + "' but is marked " +
                  (transition.is_tick ? "<tick/> (the tick transition must be silent)" : "<silent/>"));
    } else if (expert && !validExpertName(*expert)) {
      scheduleProblem(annotation.GetLineNum(), "expert name '" + *expert + "' of transition '" + id +
                                            "' must be letters, digits, '_', '-' or '.'");
    } else if (!expert && !silent) {
      scheduleProblem(annotation.GetLineNum(),
              "transition '" + id + "' names no expert: add <expert>NAME</expert>, or <silent/> "
              "for a join or fork");
    }
    if (expert) transition.expert = *expert;
  }

  // Policies apply to experts only, and retries only to a retry policy.
  void checkPolicy(const TransitionOptions& options, Transition& transition) {
    const std::string& id = transition.id;
    FiringPolicy& policy = transition.policy;
    const bool silent = options.marked_silent || transition.is_tick;
    if (silent && options.has_policy)
      scheduleProblem(options.policy_line, "transition '" + id +
                               "' is silent: timeouts, retries and policies apply to experts only");
    const bool uses_retry = policy.on_timeout == ExpiryAction::Retry ||
                            policy.on_failure == ExpiryAction::Retry;
    if (uses_retry && !options.retries_given) policy.retries = 1;
    if (uses_retry && options.retries_given && policy.retries == 0)
      scheduleProblem(options.policy_line, "transition '" + id + "' has a retry policy with <retries>0</retries>");
    if (!uses_retry && (options.retries_given || options.after_retries_given))
      scheduleProblem(options.policy_line, "transition '" + id + "' gives <retries>/<after_retries> but neither "
                           "<on_timeout> nor <on_failure> is retry");
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
    if (const std::string kind = specialArcKind(e); !kind.empty()) {
      problem(arc.line, "arc '" + arc.id + "' is " + kind + " arc; only place/transition nets (normal arcs) are read");
      arcs_refused_ = true;
      return;
    }
    int line = arc.line;
    if (const auto text = labelText(e, "inscription", &line)) {
      const TokenCount count = parseTokenCount(text->empty() ? "1" : *text);
      const auto weight = count.coloured ? std::nullopt : count.value;
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

  // "an inhibitor" for an inhibitor arc (PIPE's <type value="inhibitor"/>,
  // a type attribute, a <type><text> label), "" for a normal one.
  static std::string specialArcKind(const XMLElement& arc) {
    std::string kind = trim(arc.Attribute("type"));
    for (const XMLElement* c = arc.FirstChildElement(); c && kind.empty(); c = c->NextSiblingElement()) {
      if (!isName(c->Name(), "type") && !isName(c->Name(), "arctype")) continue;
      kind = trim(c->Attribute("value"));
      if (kind.empty())
        if (const XMLElement* text = firstChild(*c, "text")) kind = trim(text->GetText());
      if (kind.empty()) kind = trim(c->GetText());
    }
    const std::string k = lowercase(kind);
    if (k.empty() || k == "normal" || k == "regular" || k == "standard") return "";
    if (k.find("inhibitor") != std::string::npos) return "an inhibitor";
    if (k.find("reset") != std::string::npos) return "a reset";
    if (k.find("read") != std::string::npos || k.find("test") != std::string::npos) return "a read";
    return "a '" + kind + "'";
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
        const std::string message = "second arc from '" + arc.source + "' to '" + arc.target +
                                    "' (first at line " + std::to_string(previous->second) + ")";
        if (options_.schedule) {
          problem(arc.line, message + "; use one arc with a weight");
          continue;
        }
        // Any P/T net: parallel arcs act as one arc of their summed weight.
        net_.warnings.push_back(net_.file + ":" + std::to_string(arc.line) + ": " + message +
                                ": read as one arc with the weights added");
        std::vector<ArcEnd>& ends = source->kind == NodeKind::Place ? net_.transitions[target->index].inputs
                                                                    : net_.transitions[source->index].outputs;
        const int place = source->kind == NodeKind::Place ? source->index : target->index;
        for (ArcEnd& end : ends)
          if (end.place == place) end.weight += arc.weight;
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
    if (net_.places.empty()) scheduleProblem(net_line, "the net has no places");
    if (net_.transitions.empty()) scheduleProblem(net_line, "the net has no transitions");
    std::vector<int> ticks;
    for (size_t i = 0; i < net_.transitions.size(); ++i) {
      const Transition& t = net_.transitions[i];
      if (t.is_tick) ticks.push_back(static_cast<int>(i));
      // A refused arc already explains a missing input.
      if (t.inputs.empty() && !arcs_refused_)
        scheduleProblem(t.line, "transition '" + t.id + "' has no input place, so it would fire without end");
    }
    if (ticks.empty()) {
      scheduleProblem(net_line, "no tick transition: mark the silent transition that closes a tick with "
                        "<toolspecific tool=\"beft\" version=\"1\"><tick/></toolspecific>");
    } else if (ticks.size() > 1) {
      for (size_t i = 1; i < ticks.size(); ++i)
        scheduleProblem(net_.transitions[ticks[i]].line,
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

  PnmlReadOptions options_;
  Net net_;
  std::vector<std::string> problems_;
  std::map<std::string, DeclaredId> ids_;
  std::vector<PendingArc> arcs_;
  bool arcs_refused_ = false;
};

}  // namespace

NetError::NetError(std::vector<std::string> problems)
    : std::runtime_error(joinLines(problems)), problems_(std::move(problems)) {}

Net readPnmlFile(const std::string& path, const PnmlReadOptions& options) {
  struct stat info {};
  if (stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    throw NetError({path + ": is a directory, not a PNML file"});
  std::ifstream in(path, std::ios::binary);
  if (!in) throw NetError({path + ": cannot open the file: " + std::strerror(errno)});
  std::ostringstream text;
  text << in.rdbuf();
  return readPnmlString(text.str(), path, options);
}

Net readPnmlString(const std::string& bytes, const std::string& display_name, const PnmlReadOptions& options) {
  std::string text;
  try {
    text = xmlTextAsUtf8(bytes);
  } catch (const std::exception& e) {
    throw NetError({display_name + ":1: " + e.what()});
  }
  tinyxml2::XMLDocument document;
  document.Parse(text.c_str(), text.size());
  PnmlReader reader(display_name, options);
  return reader.read(document);
}

}  // namespace beft::arbiter

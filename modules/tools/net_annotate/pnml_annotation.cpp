#include "tools/net_annotate/pnml_annotation.hpp"

#include <tinyxml2.h>

#include <cstring>
#include <set>
#include <stdexcept>

#include "lib/petri/xml_encoding.hpp"

namespace beft::net_annotate {

namespace {

using tinyxml2::XMLElement;

const char* localName(const char* name) {
  const char* colon = std::strrchr(name, ':');
  return colon ? colon + 1 : name;
}

bool isName(const XMLElement& e, const char* local) { return std::strcmp(localName(e.Name()), local) == 0; }

// "pnml:" when the element's name has that prefix, so new PNML elements match it.
std::string prefixOf(const XMLElement& e) {
  const char* colon = std::strrchr(e.Name(), ':');
  return colon ? std::string(e.Name(), colon + 1) : "";
}

std::string trimmed(const char* text) {
  if (!text) return "";
  std::string s(text);
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

std::string nameOf(const XMLElement& transition) {
  for (const XMLElement* e = transition.FirstChildElement(); e; e = e->NextSiblingElement()) {
    if (!isName(*e, "name")) continue;
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
      if (isName(*c, "text") || isName(*c, "value")) return trimmed(c->GetText());
    return trimmed(e->GetText());
  }
  return "";
}

void collectTransitions(XMLElement& container, std::vector<XMLElement*>& out) {
  for (XMLElement* e = container.FirstChildElement(); e; e = e->NextSiblingElement()) {
    if (isName(*e, "transition")) out.push_back(e);
    else if (isName(*e, "page")) collectTransitions(*e, out);
  }
}

XMLElement* beftAnnotation(XMLElement& transition) {
  for (XMLElement* e = transition.FirstChildElement(); e; e = e->NextSiblingElement())
    if (isName(*e, "toolspecific") && trimmed(e->Attribute("tool")) == "beft") return e;
  return nullptr;
}

class Annotator {
 public:
  Annotator(std::string file, tinyxml2::XMLDocument& document) : file_(std::move(file)), document_(document) {}

  XMLElement& chooseNet(const std::string& net_id) {
    XMLElement* root = document_.RootElement();
    if (!root || !isName(*root, "pnml")) fail(root ? root->GetLineNum() : 1, "the root element is not <pnml>");
    XMLElement* first = nullptr;
    for (XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
      if (!isName(*e, "net")) continue;
      if (!first) first = e;
      if (!net_id.empty() && trimmed(e->Attribute("id")) == net_id) return *e;
    }
    if (!first) fail(root->GetLineNum(), "<pnml> holds no <net>");
    if (!net_id.empty()) fail(root->GetLineNum(), "no <net> with id '" + net_id + "'");
    return *first;
  }

  // The one transition with this id, else the one with this name.
  XMLElement* find(const std::vector<XMLElement*>& transitions, const std::string& key) {
    for (XMLElement* t : transitions)
      if (trimmed(t->Attribute("id")) == key) return t;
    XMLElement* found = nullptr;
    for (XMLElement* t : transitions) {
      if (nameOf(*t) != key) continue;
      if (found)
        fail(t->GetLineNum(), "two transitions are named '" + key + "' ('" + trimmed(found->Attribute("id")) +
                                  "' and '" + trimmed(t->Attribute("id")) + "'): give the id");
      found = t;
    }
    if (!found) fail(1, "the net has no transition with id or name '" + key + "'");
    return found;
  }

  void annotate(XMLElement& transition, const std::string& expert, bool tick, const std::string& level) {
    if (XMLElement* old = beftAnnotation(transition)) transition.DeleteChild(old);
    XMLElement* tool = document_.NewElement((prefixOf(transition) + "toolspecific").c_str());
    tool->SetAttribute("tool", "beft");
    tool->SetAttribute("version", "1");
    if (tick) {
      tool->InsertNewChildElement("tick");
    } else if (expert.empty()) {
      tool->InsertNewChildElement("silent");
    } else {
      tool->InsertNewChildElement("expert")->SetText(expert.c_str());
    }
    if (!level.empty()) tool->InsertNewChildElement("level")->SetText(level.c_str());
    transition.InsertEndChild(tool);
  }

  [[noreturn]] void fail(int line, const std::string& message) {
    throw std::runtime_error(file_ + ":" + std::to_string(line) + ": " + message);
  }

 private:
  std::string file_;
  tinyxml2::XMLDocument& document_;
};

}  // namespace

AnnotationResult annotatePnml(const std::string& bytes, const std::string& display_name,
                              const AnnotationRequest& request) {
  const std::string text = arbiter::xmlTextAsUtf8(bytes);
  // Every element, attribute and comment is kept; tinyxml2 re-indents the
  // layout (it does not keep whitespace between elements).
  tinyxml2::XMLDocument document;
  if (document.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    throw std::runtime_error(display_name + ":" + std::to_string(std::max(1, document.ErrorLineNum())) +
                             ": not well-formed XML (" + document.ErrorName() + ")");
  Annotator annotator(display_name, document);
  XMLElement& net = annotator.chooseNet(request.net_id);
  std::vector<XMLElement*> transitions;
  collectTransitions(net, transitions);

  // Each transition's role, by its id; a transition named twice is an error.
  struct Role {
    std::string expert, level, given_as;
    bool tick = false, silent = false;
  };
  std::map<const XMLElement*, Role> roles;
  const auto role = [&](const std::string& key, const char* what) -> Role& {
    XMLElement* t = annotator.find(transitions, key);
    Role& r = roles[t];
    if (!r.given_as.empty() && std::strcmp(what, "level") != 0)
      annotator.fail(t->GetLineNum(), "transition '" + trimmed(t->Attribute("id")) + "' is given two roles (" +
                                          r.given_as + " and " + what + ")");
    if (std::strcmp(what, "level") != 0) r.given_as = what;
    return r;
  };
  for (const auto& [key, expert] : request.experts) role(key, ("expert " + expert).c_str()).expert = expert;
  if (!request.tick.empty()) role(request.tick, "the tick").tick = true;
  for (const auto& key : request.silent) role(key, "silent").silent = true;
  for (const auto& [key, level] : request.levels) role(key, "level").level = level;

  AnnotationResult result;
  for (XMLElement* t : transitions) {
    const std::string id = trimmed(t->Attribute("id"));
    const auto found = roles.find(t);
    if (found == roles.end() || found->second.given_as.empty()) {
      const std::string level = found == roles.end() ? "" : found->second.level;
      if (beftAnnotation(*t) && level.empty()) {
        result.kept.push_back(id);
        continue;
      }
      result.made_silent.push_back(id);
      annotator.annotate(*t, "", false, level);
      continue;
    }
    const Role& r = found->second;
    annotator.annotate(*t, r.expert, r.tick, r.level);
  }
  // The text is UTF-8 now; a declaration naming another encoding would lie.
  if (tinyxml2::XMLNode* first = document.FirstChild(); first && first->ToDeclaration()) {
    std::string declaration = first->Value();
    const std::string encoding = arbiter::declaredXmlEncoding("<?" + declaration + "?>");
    if (!encoding.empty()) {
      const auto at = declaration.find(encoding);
      declaration.replace(at, encoding.size(), "UTF-8");
      first->SetValue(declaration.c_str());
    }
  }
  tinyxml2::XMLPrinter printer;
  document.Print(&printer);
  result.text = printer.CStr();
  return result;
}

}  // namespace beft::net_annotate

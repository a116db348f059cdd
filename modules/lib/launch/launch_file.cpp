#include "lib/launch/launch_file.hpp"

#include <filesystem>
#include <tinyxml2.h>

#include <set>

#include "lib/wire/run_identity.hpp"

namespace beft::launch {

namespace {

std::string where(const std::string& file, int line) { return file + ":" + std::to_string(line) + ": "; }

// Replaces ${name} by its value; unknown names are an error.
std::string substitute(const std::string& text, const std::map<std::string, std::string>& values,
                       const std::string& file, int line) {
  std::string out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const auto start = text.find("${", pos);
    if (start == std::string::npos) {
      out += text.substr(pos);
      break;
    }
    const auto end = text.find('}', start);
    if (end == std::string::npos) throw LaunchError(where(file, line) + "unterminated '${' in '" + text + "'");
    out += text.substr(pos, start - pos);
    const std::string name = text.substr(start + 2, end - start - 2);
    auto it = values.find(name);
    if (it == values.end())
      throw LaunchError(where(file, line) + "unknown variable '${" + name + "}' (declare it with <arg>)");
    out += it->second;
    pos = end + 1;
  }
  return out;
}

const char* attribute(const tinyxml2::XMLElement* e, const char* name, const std::string& file, bool required) {
  const char* value = e->Attribute(name);
  if (!value && required)
    throw LaunchError(where(file, e->GetLineNum()) + "<" + e->Name() + "> needs attribute '" + name + "'");
  return value;
}

// A process with if="${arg}" starts only when the substituted value is 1 or
// true (0, false or empty: not started), as roslaunch's if.
bool startsWhen(const tinyxml2::XMLElement* e, const std::map<std::string, std::string>& args,
                const std::string& path) {
  const char* condition = e->Attribute("if");
  if (condition == nullptr) return true;
  const std::string value = substitute(condition, args, path, e->GetLineNum());
  if (value == "1" || value == "true") return true;
  if (value == "0" || value == "false" || value.empty()) return false;
  throw LaunchError(where(path, e->GetLineNum()) + "if must be 1, true, 0, false or empty, not '" + value + "'");
}

}  // namespace

std::vector<std::string> splitArguments(const std::string& text) {
  std::vector<std::string> parts;
  std::string current;
  bool in_token = false;
  char quote = 0;
  for (char c : text) {
    if (quote) {
      if (c == quote) quote = 0;
      else current += c;
    } else if (c == '"' || c == '\'') {
      quote = c;
      in_token = true;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      if (in_token) parts.push_back(current);
      current.clear();
      in_token = false;
    } else {
      current += c;
      in_token = true;
    }
  }
  if (quote) throw LaunchError("unbalanced quote in '" + text + "'");
  if (in_token) parts.push_back(current);
  return parts;
}

std::map<std::string, std::string> parseSettings(const std::vector<std::string>& settings) {
  std::map<std::string, std::string> values;
  for (const auto& setting : settings) {
    const auto eq = setting.find('=');
    if (eq == std::string::npos || eq == 0) throw LaunchError("--set '" + setting + "' is not NAME=VALUE");
    values[setting.substr(0, eq)] = setting.substr(eq + 1);
  }
  return values;
}

LaunchSpec loadLaunchFile(const std::string& path, const std::map<std::string, std::string>& overrides) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
    const int line = doc.ErrorLineNum();
    throw LaunchError(where(path, line) + "cannot read launch file: " + (doc.ErrorStr() ? doc.ErrorStr() : "?"));
  }
  const auto* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "launch")
    throw LaunchError(where(path, root ? root->GetLineNum() : 1) + "the root element must be <launch>");

  LaunchSpec spec;
  spec.file = path;
  spec.name = root->Attribute("name") ? root->Attribute("name") : "run";
  std::set<std::string> declared;
  for (const auto* e = root->FirstChildElement("arg"); e; e = e->NextSiblingElement("arg")) {
    const std::string name = attribute(e, "name", path, true);
    const char* def = e->Attribute("default");
    spec.args[name] = def ? def : "";
    declared.insert(name);
  }
  for (const auto& [name, value] : overrides) {
    if (!declared.count(name) && name != "lcm_url")
      throw LaunchError(path + ": --set " + name + ": the launch file declares no <arg name=\"" + name + "\">");
    spec.args[name] = value;
  }
  if (!spec.args.count("lcm_url")) spec.args["lcm_url"] = "";

  std::set<std::string> names;
  for (const auto* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string element = e->Name();
    if (element == "arg") continue;
    if (element != "process")
      throw LaunchError(where(path, e->GetLineNum()) + "unknown element <" + element + "> (expected <arg> or <process>)");
    ProcessSpec p;
    p.line = e->GetLineNum();
    p.name = attribute(e, "name", path, true);
    if (!names.insert(p.name).second)
      throw LaunchError(where(path, p.line) + "duplicate process name '" + p.name + "'");
    if (!startsWhen(e, spec.args, path)) continue;
    p.command = substitute(attribute(e, "command", path, true), spec.args, path, p.line);
    if (const char* a = e->Attribute("args")) {
      try {
        p.args = splitArguments(substitute(a, spec.args, path, p.line));
      } catch (const LaunchError& err) {
        throw LaunchError(where(path, p.line) + err.what());
      }
    }
    if (const char* g = e->Attribute("group")) p.group = g;
    if (const char* h = e->Attribute("host")) p.host = substitute(h, spec.args, path, p.line);
    if (const char* r = e->Attribute("restart")) {
      const std::string policy = r;
      if (policy == "never") p.restart = RestartPolicy::Never;
      else if (policy == "on-failure") p.restart = RestartPolicy::OnFailure;
      else throw LaunchError(where(path, p.line) + "restart must be 'never' or 'on-failure', not '" + policy + "'");
    }
    if (e->Attribute("max_restarts") && (e->QueryIntAttribute("max_restarts", &p.max_restarts) != tinyxml2::XML_SUCCESS || p.max_restarts < 0))
      throw LaunchError(where(path, p.line) + "max_restarts must be an integer >= 0");
    if (const char* role = e->Attribute("role")) {
      if (std::string(role) != "arbiter")
        throw LaunchError(where(path, p.line) + "unknown role '" + role + "' (the only role is 'arbiter')");
      p.is_arbiter = true;
    }
    if (const char* append = e->Attribute("lcm_url")) p.append_lcm_url = std::string(append) != "0";
    if (const char* priority = e->Attribute("priority")) {
      const std::string value = priority;
      if (value == "normal") p.priority = Priority::Normal;
      else if (value == "background") p.priority = Priority::Background;
      else throw LaunchError(where(path, p.line) + "priority must be 'normal' or 'background', not '" + value + "'");
    }
    for (const auto* attr = e->FirstAttribute(); attr; attr = attr->Next()) {
      static const std::set<std::string> known = {"name",         "command", "args",    "group",    "host", "restart",
                                                  "max_restarts", "role",    "lcm_url", "priority", "if"};
      if (!known.count(attr->Name()))
        throw LaunchError(where(path, p.line) + "unknown attribute '" + attr->Name() + "' on <process>");
    }
    spec.processes.push_back(p);
  }
  if (spec.processes.empty()) throw LaunchError(where(path, root->GetLineNum()) + "no <process> in the launch file");
  return spec;
}

int64_t launchDescriptionOf(const std::string& launch_file, const std::map<std::string, std::string>& args) {
  std::string description = std::filesystem::path(launch_file).filename().string();
  for (const auto& [name, value] : args) {
    if (name == "lcm_url" || (name.size() >= 5 && name.compare(name.size() - 5, 5, "_host") == 0)) continue;
    description += "\n" + name + "=" + value;
  }
  return wire::runDescriptionHash(description);
}

}  // namespace beft::launch

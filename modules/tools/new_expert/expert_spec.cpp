#include "tools/new_expert/expert_spec.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

namespace beft::new_expert {

namespace fs = std::filesystem;

namespace {

const std::set<std::string>& cppKeywords() {
  static const std::set<std::string> words = {
      "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
      "char", "class", "compl", "const", "constexpr", "const_cast", "continue", "decltype", "default", "delete",
      "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for",
      "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
      "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast",
      "return", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "struct", "switch",
      "template", "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename", "union",
      "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq",
      // names the generated code or the expert framework already use in namespace beft
      "expert", "channels", "std", "beft", "test", "testing_support"};
  return words;
}

// Whether some CMakeLists.txt under root/modules makes an executable `program`.
bool programExists(const fs::path& root, const std::string& program) {
  const fs::path modules = root / "modules";
  if (!fs::is_directory(modules)) return false;
  const std::regex executable("add_executable\\(\\s*" + program + "[\\s)]");
  for (const auto& entry : fs::recursive_directory_iterator(modules)) {
    if (entry.path().filename() != "CMakeLists.txt") continue;
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    if (std::regex_search(text, executable)) return true;
  }
  return false;
}

void checkName(const ExpertRequest& request, const std::string& program) {
  const std::string& name = request.name;
  if (!std::regex_match(name, std::regex("[a-z][a-z0-9_]*")) || name.back() == '_' ||
      name.find("__") != std::string::npos)
    throw SpecError("expert name '" + name +
                    "' is not a lowercase identifier (a-z first, then a-z, 0-9, single '_' between words)");
  if (cppKeywords().count(name)) throw SpecError("expert name '" + name + "' is a C++ keyword or a name in use");
  for (const auto& root : {request.root, request.source_root}) {
    for (const char* folder : {"modules/experts/", "tests/experts/"})
      if (fs::exists(fs::path(root) / (folder + name)))
        throw SpecError("an expert named '" + name + "' already exists: " + folder + name);
    if (programExists(root, program))
      throw SpecError("a program " + program + " already exists under modules/: choose another name");
  }
}

KnownChannel tableChannel(const std::string& name, const char* option) {
  const KnownChannel* channel = findChannel(name);
  if (channel == nullptr)
    throw SpecError(std::string(option) + " " + name + ": no such channel in BEFT_CHANNELS (lib/common/channels.hpp); " +
                    "known: " + channelNames() + "; for a new one use --new-channel " + name + ":TYPE_t");
  return *channel;
}

KnownChannel readChannel(const std::string& name) {
  KnownChannel channel = tableChannel(name, "--reads");
  if (name == "OBSTACLE_MAP" || name == "HYPOTHESES")
    throw SpecError("--reads " + name + ": a keyframed channel; read it through expert::" +
                    std::string(name == "OBSTACLE_MAP" ? "ObstacleMapInput" : "HypothesesInput") +
                    " (lib/expert/), by hand, as the exploration expert does");
  if (!channel.has_utime || !channel.has_tick)
    throw SpecError("--reads " + name + ": " + channel.type + " has no utime and tick, so a TickInput cannot keep it "
                    "by tick; read it with expert::HandledInput (lib/expert/ports.hpp) by hand");
  return channel;
}

KnownChannel newChannel(const std::string& given, const ExpertRequest& request) {
  const std::smatch parts = [&given] {
    std::smatch m;
    if (!std::regex_match(given, m, std::regex("([A-Z][A-Z0-9_]*):([a-z][a-z0-9_]*_t)")))
      throw SpecError("--new-channel " + given + ": write it CHANNEL:type_t, e.g. THREATS:threats_t");
    return m;
  }();
  const std::string name = parts[1], type = parts[2];
  if (findChannel(name) != nullptr)
    throw SpecError("--new-channel " + name + ": already in the channel table; use --writes " + name);
  for (const auto& root : {request.root, request.source_root})
    if (fs::exists(fs::path(root) / "lcmtypes" / (type + ".lcm")))
      throw SpecError("--new-channel " + given + ": lcmtypes/" + type + ".lcm exists; add the channel of it to " +
                      "BEFT_CHANNELS first, then use --writes " + name);
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  return KnownChannel{"k" + camelCase(lower), name, type, true, true};  // its .lcm is written with utime and tick
}

}  // namespace

std::string camelCase(const std::string& snake) {
  std::string out;
  bool upper = true;
  for (const char c : snake) {
    if (c == '_') {
      upper = true;
      continue;
    }
    out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  return out;
}

std::string usualExpertOfLevel(const std::string& level) {
  if (level == "low") return "geometry";
  if (level == "mid") return "acoustic_labels";
  return "dw";
}

ExpertSpec checkRequest(const ExpertRequest& request) {
  ExpertSpec spec;
  spec.name = request.name;
  spec.program = "beft-" + request.name;
  std::replace(spec.program.begin(), spec.program.end(), '_', '-');
  checkName(request, spec.program);
  spec.class_name = camelCase(request.name) + "Expert";
  if (request.level != "low" && request.level != "mid" && request.level != "high")
    throw SpecError("--level " + request.level + ": one of low, mid, high");
  spec.level = request.level;
  spec.after = request.after.empty() ? usualExpertOfLevel(request.level) : request.after;
  std::set<std::string> seen;
  for (const auto& name : request.reads) {
    if (!seen.insert("r" + name).second) throw SpecError("--reads " + name + " given twice");
    spec.reads.push_back(readChannel(name));
  }
  for (const auto& name : request.writes) {
    if (!seen.insert("w" + name).second) throw SpecError("--writes " + name + " given twice");
    spec.writes.push_back(tableChannel(name, "--writes"));
  }
  for (const auto& given : request.new_channels) {
    spec.new_channels.push_back(newChannel(given, request));
    if (!seen.insert("w" + spec.new_channels.back().name).second) throw SpecError("--new-channel " + given + " given twice");
    spec.writes.push_back(spec.new_channels.back());
  }
  if (spec.writes.empty())
    throw SpecError("no --writes CHANNEL (nor --new-channel CHANNEL:type_t): an expert publishes something");
  spec.root = request.root;
  spec.source_root = request.source_root;
  return spec;
}

}  // namespace beft::new_expert

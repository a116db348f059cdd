#include "tools/new_expert/manual_steps.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "tools/new_expert/net_steps.hpp"

namespace beft::new_expert {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> linesOf(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string launchStep(const ExpertSpec& spec) {
  const std::string file = "scenarios/launch/mission.xml";
  const auto lines = linesOf(fs::path(spec.source_root) / file);
  std::size_t after = 0;
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (lines[i].find("<process name=\"" + spec.after + "\"") != std::string::npos) after = i + 1;
  const std::string indent = after > 0 ? lines[after - 1].substr(0, lines[after - 1].find('<')) : "  ";
  const std::string where = after > 0 ? "after line " + std::to_string(after) + " (the process " + spec.after + ")"
                                      : "before the arbiter's <process> line";
  return file + ": " + where + ", add:\n" + indent + "<process name=\"" + spec.name +
         "\" host=\"${expert_host}\" command=\"" + spec.program + "\" group=\"" + spec.level +
         "\" restart=\"on-failure\"/>\n\n";
}

// The channel whose table line a new channel of the level's output copies.
std::string referenceChannel(const std::string& level) {
  if (level == "low") return "GEOMETRY";
  if (level == "mid") return "LABELS_VISUAL";
  return "DYNAMIC_WEIGHTS";
}

// The column most X(...) lines of the table put their backslash in.
std::size_t backslashColumn(const std::vector<std::string>& table_lines) {
  std::map<std::size_t, int> widths;
  for (const auto& line : table_lines)
    if (line.rfind("  X(", 0) == 0 && line.back() == '\\') ++widths[line.size() - 1];
  std::size_t width = 94;
  int most = 0;
  for (const auto& [column, count] : widths)
    if (count > most) {
      width = column;
      most = count;
    }
  return width;
}

// The new channel's X(...) line, written as the reference channel's line
// (whatever columns follow the type, such as its plane, are kept) and
// padded as its neighbours; "" if the table has no line for the reference.
std::string channelLine(const KnownChannel& channel, const std::string& reference,
                        const std::vector<std::string>& table_lines) {
  for (const auto& line : table_lines) {
    const std::size_t open = line.find("X(");
    if (open == std::string::npos || line.find("\"" + reference + "\"") == std::string::npos) continue;
    const std::size_t close = line.find(')', open);
    const std::string args = line.substr(open + 2, close - open - 2);  // "kX, "X", x_t, Data"
    std::size_t after_type = args.find(',', args.find(',', args.find(',') + 1) + 1);
    const std::string rest = after_type == std::string::npos ? "" : args.substr(after_type);
    std::string text = "  X(" + channel.constant + ", \"" + channel.name + "\", " + channel.type + rest + ")";
    const std::size_t width = backslashColumn(table_lines);
    if (text.size() < width) text += std::string(width - text.size(), ' ');
    return text + "\\";
  }
  return "";
}

std::string channelSteps(const ExpertSpec& spec) {
  if (spec.new_channels.empty()) return "";
  const std::string file = "modules/lib/common/channels.hpp";
  const auto lines = linesOf(fs::path(spec.source_root) / file);
  const std::string reference = referenceChannel(spec.level);
  std::string text = file + " (for each new channel; its lcmtypes/*.lcm is written, with utime and tick):\n";
  for (const auto& channel : spec.new_channels) {
    const std::string line = channelLine(channel, reference, lines);
    text += "  add beside the other message includes:\n#include <beft/" + channel.type + ".hpp>\n";
    if (line.empty()) {
      text += "  add it to BEFT_CHANNELS as X(" + channel.constant + ", \"" + channel.name + "\", " + channel.type +
              ", ...), written as the other outputs of experts are\n";
      continue;
    }
    text += "  add to BEFT_CHANNELS, after the line of " + reference + ":\n" + line + "\n";
    if (std::count(line.begin(), line.end(), ',') < 3)
      text += "  and add " + channel.name + " to the data-plane set of isDataPlaneChannel: an expert's output of a tick\n";
  }
  return text + "\n";
}

std::string buildSteps(const ExpertSpec& spec) {
  return "Build and test it (CMake finds the new folders when it configures):\n"
         "  cmake -S . -B build && cmake --build build --target " + spec.program + " test_" + spec.name +
         "_expert\n  build/bin/test_" + spec.name + "_expert\n"
         "Run it alone:\n  build/bin/" + spec.program + " --help\n  build/bin/" + spec.program +
         " --interface\n  ./beft launch scenarios/launch/mission.xml --new-port --except " + spec.name +
         "   (then start it by hand)\n"
         "Check each net changed: ./beft net check scenarios/nets/NET.pnml\n"
         "The mission tests (tests/system/test_mission.cpp) pin a digest of every data-plane message: a new\n"
         "output channel adds messages there to pin.\n";
}

}  // namespace

std::string manualSteps(const ExpertSpec& spec, const std::vector<GeneratedFile>& written) {
  std::string text = "Written:\n";
  for (const auto& file : written) text += "  " + file.path + "\n";
  text += "\nLeft to do by hand:\n\n" + channelSteps(spec);
  text += "The schedules: " + spec.name + " fires where a net has a transition for it.\n\n" + netSteps(spec);
  text += "The launch file, so a run starts it:\n" + launchStep(spec);
  return text + buildSteps(spec);
}

}  // namespace beft::new_expert

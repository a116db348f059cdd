#include "tools/new_expert/code_blocks.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <vector>

namespace beft::new_expert {

namespace {

const char* const kGroundTruth = "GT_OBJECTS";  // sent when the scene changes: expert::SceneInput keeps it by tick

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::string channelList(const std::vector<KnownChannel>& channels) {
  std::string text;
  for (const auto& channel : channels) text += (text.empty() ? "" : ", ") + channel.name;
  return text.empty() ? "none" : text;
}

std::string messageIncludes(const ExpertSpec& spec) {
  std::set<std::string> types;
  for (const auto* list : {&spec.reads, &spec.writes})
    for (const auto& channel : *list) types.insert(channel.type);
  std::string text = "\n";
  for (const auto& type : types) text += "#include <beft/" + type + ".hpp>\n";
  return text;
}

std::string ports(const ExpertSpec& spec) {
  std::string text = "\n";
  for (const auto& channel : spec.reads)
    text += channel.name == kGroundTruth ? "  expert::SceneInput scene_{*this};\n"
                                         : "  expert::TickInput<" + channel.type + "> " + inputMember(channel) +
                                               "{*this, channels::" + channel.constant + "};\n";
  for (const auto& channel : spec.writes)
    text += "  expert::OutputPort<" + channel.type + "> " + outputMember(channel) + "{*this, channels::" +
            channel.constant + "};\n";
  return text;
}

std::string inputChecks(const ExpertSpec& spec) {
  std::string text;
  for (const auto& channel : spec.reads)
    text += "  if (!" + inputMember(channel) + ".has(firing.tick))\n    return expert::Outcome::failure(\"no " +
            channel.name + " for tick \" + std::to_string(firing.tick));\n";
  return text;
}

// One message per output: what a message of the tick needs at least.
std::string publishing(const ExpertSpec& spec) {
  std::string text;
  for (const auto& channel : spec.writes) {
    text += "  {\n    " + channel.type + " message{};\n";
    if (channel.has_utime) text += "    message.utime = firing.utime;\n";
    if (channel.has_tick) text += "    message.tick = firing.tick;\n";
    text += "    " + outputMember(channel) + ".publish(out, message);\n  }\n";
  }
  return text;
}

std::string testDeliveries(const ExpertSpec& spec) {
  std::string text = spec.reads.empty() ? "  (void)expert;\n  (void)tick;\n" : "";
  for (const auto& channel : spec.reads)
    text += "  {\n    " + channel.type + " message{};\n    message.utime = firing(\"" + spec.name +
            "\", tick).utime;\n    message.tick = tick;\n    ASSERT_TRUE(deliver(expert, channels::" + channel.constant +
            ", message));\n  }\n";
  return text;
}

std::string testExpectations(const ExpertSpec& spec) {
  const bool stamped = std::any_of(spec.writes.begin(), spec.writes.end(),
                                   [](const KnownChannel& c) { return c.has_tick || c.has_utime; });
  std::string text = stamped ? "" : "  (void)tick;\n";
  for (const auto& channel : spec.writes) {
    text += "  for (const auto& message : out.on<" + channel.type + ">(channels::" + channel.constant + ")) {\n";
    if (channel.has_tick) text += "    EXPECT_EQ(message.tick, tick);\n";
    if (channel.has_utime) text += "    EXPECT_EQ(message.utime, firing(\"" + spec.name + "\", tick).utime);\n";
    text += "    ++count;\n  }\n";
  }
  return text;
}

std::string inputTests(const ExpertSpec& spec) {
  if (spec.reads.empty()) return "";
  const std::string& c = spec.class_name;
  const std::string f = "firing(\"" + spec.name + "\", ";
  return "\nTEST(" + c + ", WaitsForItsInputsOfTheFiredTick) {\n  " + c + " expert;\n  expert.startUp();\n" +
         "  EXPECT_FALSE(expert.inputsReady(" + f + "5)));\n  CollectingOutput out;\n" +
         "  const expert::Outcome outcome = expert.fire(" + f + "5), out);\n  EXPECT_FALSE(outcome.ok);\n" +
         "  EXPECT_NE(outcome.message.find(\"for tick 5\"), std::string::npos) << outcome.message;\n" +
         "  EXPECT_TRUE(out.published.empty());\n  deliverInputs(expert, 5);\n" +
         "  EXPECT_TRUE(expert.inputsReady(" + f + "5)));\n  EXPECT_FALSE(expert.inputsReady(" + f + "6)));\n}\n";
}

}  // namespace

std::string inputMember(const KnownChannel& channel) {
  return channel.name == kGroundTruth ? "scene_" : lower(channel.name) + "_";
}

std::string outputMember(const KnownChannel& channel) { return lower(channel.name) + "_out_"; }

std::map<std::string, std::string> templateValues(const ExpertSpec& spec) {
  const bool reads_scene =
      std::any_of(spec.reads.begin(), spec.reads.end(), [](const KnownChannel& c) { return c.name == kGroundTruth; });
  std::string level_word = spec.level;
  level_word[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(level_word[0])));
  return {{"name", spec.name},
          {"class", spec.class_name},
          {"program", spec.program},
          {"own_header", "\"experts/" + spec.name + "/" + spec.name + "_expert.hpp\""},
          {"level", spec.level},
          {"level_word", level_word},
          {"reads_list", channelList(spec.reads)},
          {"writes_list", channelList(spec.writes)},
          {"message_includes", messageIncludes(spec)},
          {"port_includes", reads_scene ? "#include \"lib/expert/scene_input.hpp\"\n" : ""},
          {"ports", ports(spec)},
          {"input_checks", inputChecks(spec)},
          {"publishing", publishing(spec)},
          {"deliveries", testDeliveries(spec)},
          {"expectations", testExpectations(spec)},
          {"write_count", std::to_string(spec.writes.size())},
          {"input_tests", inputTests(spec)}};
}

}  // namespace beft::new_expert

#include "tools/new_expert/expert_command_line.hpp"

#include "lib/common/command_line.hpp"

namespace beft::new_expert {

namespace {

const char* const kDescription =
    "Writes a new expert that compiles and is tested, and prints the steps left to do by hand.\n"
    "Written (under the repository, or --out DIR):\n"
    "  modules/experts/NAME/{CMakeLists.txt, main.cpp, NAME_expert.hpp, NAME_expert.cpp}: the class, with a\n"
    "    TickInput member per --reads channel (expert::SceneInput for GT_OBJECTS), an OutputPort per --writes\n"
    "    channel, the parameter every_n_ticks (1..1000000) and a fire() that, once the inputs of the fired tick\n"
    "    are there, publishes on every output a message stamped with that tick (at multiples of every_n_ticks);\n"
    "    its process is beft-NAME (underscores become dashes);\n"
    "  tests/experts/NAME/{CMakeLists.txt, test_NAME_expert.cpp}: the class without LCM; fails if fire() does\n"
    "    not publish;\n"
    "  lcmtypes/TYPE.lcm for each --new-channel CHANNEL:TYPE (utime and tick; add the fields it carries).\n"
    "Printed: the exact text to add to every net in scenarios/nets/ (a place, a transition with the model's\n"
    "firing policy and arcs that put NAME in series right after the level's model expert: low geometry,\n"
    "mid acoustic_labels, high dw, or --after; in a net without it, after the last expert of the level), the\n"
    "launch file line, the lines of channels.hpp for a new channel, and how to build, test and run it alone.\n"
    "Refused, with exit code 2 and nothing written: a NAME that is not a lowercase identifier or exists\n"
    "(modules/experts/NAME, tests/experts/NAME, a program beft-NAME), a channel not in BEFT_CHANNELS\n"
    "(lib/common/channels.hpp), a keyframed or untimed channel to read, no output at all.\n"
    "Example: ./beft new expert threat --reads GEOMETRY LABELS_ACOUSTIC --writes TASK_COMMAND --level high";

}  // namespace

std::optional<int> parseCommandLine(int argc, char** argv, ExpertRequest& request) {
  CLI::App app(kDescription, "beft-new-expert");
  app.add_option("name", request.name, "the expert's name: a lowercase identifier, e.g. threat_map")->required();
  app.add_option("--reads", request.reads, "channels it reads by tick (names in BEFT_CHANNELS)");
  app.add_option("--writes", request.writes, "channels it publishes (names in BEFT_CHANNELS)");
  app.add_option("--new-channel", request.new_channels,
                 "a channel not in the table yet that it publishes, as CHANNEL:type_t (its .lcm is written)");
  app.add_option("--level", request.level, "its level in the schedules")
      ->check(CLI::IsMember({"low", "mid", "high"}))->capture_default_str();
  app.add_option("--after", request.after, "the expert it follows in every net (default: the level's model)");
  app.add_option("--out", request.root, "write under this root instead of the repository (for tests)");
  request.source_root = BEFT_SOURCE_DIR;
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  if (request.root.empty()) request.root = request.source_root;
  return std::nullopt;
}

}  // namespace beft::new_expert

// beft-net-annotate: makes a net drawn in a Petri-net editor an arbiter
// schedule by writing the arbiter's annotations into the editor's file.
// Run as `./beft net annotate FILE.pnml --expert T=EXPERT ... --tick T --out OUT.pnml`.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "lib/common/command_line.hpp"
#include "tools/net_annotate/pnml_annotation.hpp"
#include "lib/petri/pnml_reader.hpp"
#include "lib/common/whole_file.hpp"

namespace {

using namespace beft;

struct Options {
  std::string input, output;
  std::vector<std::string> experts, levels;
  net_annotate::AnnotationRequest request;
};

std::optional<std::pair<std::string, std::string>> splitPair(const std::string& text) {
  const auto equals = text.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == text.size()) return std::nullopt;
  return std::make_pair(text.substr(0, equals), text.substr(equals + 1));
}

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Writes the arbiter's annotations into a PNML file drawn in a Petri-net editor, keeping\n"
      "everything else in it (graphics, other tools' data), so it still opens in the editor.\n"
      "Transitions are matched by id, else by their name. A transition not named keeps the\n"
      "annotation it has, or becomes silent (a join or fork); they are listed. The result is\n"
      "then read as a schedule: exit 0 when the arbiter can run it, 1 with the problems (the\n"
      "file is written either way), 2 when the input cannot be read or annotated.",
      "beft-net-annotate");
  app.add_option("net", o.input, "PNML file")->required()->check(CLI::ExistingFile);
  app.add_option("--expert", o.experts, "TRANSITION=EXPERT: the transition fires that expert (repeatable)");
  app.add_option("--tick", o.request.tick, "the silent transition that closes a tick")->required();
  app.add_option("--silent", o.request.silent, "a transition that fires no expert (repeatable)");
  app.add_option("--level", o.levels, "TRANSITION=LABEL: a free label (world, low, mid, high) (repeatable)");
  app.add_option("--net-id", o.request.net_id, "the <net> to annotate when the file holds several");
  app.add_option("--out,-o", o.output, "where to write the annotated net")->required();
  if (const auto code = parseCommandLine(app, argc, argv)) return code;
  for (const auto& [list, target] : {std::make_pair(&o.experts, &o.request.experts),
                                     std::make_pair(&o.levels, &o.request.levels)}) {
    for (const auto& item : *list) {
      const auto pair = splitPair(item);
      if (!pair) {
        std::fprintf(stderr, "beft-net-annotate: '%s' is not TRANSITION=VALUE\n", item.c_str());
        return 2;
      }
      (*target)[pair->first] = pair->second;
    }
  }
  return std::nullopt;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

int annotate(const Options& o) {
  std::ifstream in(o.input, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  net_annotate::AnnotationResult result;
  try {
    arbiter::PnmlReadOptions any_net;
    any_net.schedule = false;
    any_net.net_id = o.request.net_id;
    arbiter::readPnmlString(bytes.str(), o.input, any_net);  // a P/T net at all?
    result = net_annotate::annotatePnml(bytes.str(), o.input, o.request);
  } catch (const arbiter::NetError& e) {
    for (const auto& problem : e.problems()) std::fprintf(stderr, "%s\n", problem.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  try {
    writeWholeFile(o.output, result.text);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beft-net-annotate: %s\n", e.what());
    return 2;
  }
  std::printf("wrote %s\n", o.output.c_str());
  if (!result.made_silent.empty()) std::printf("made silent (not named): %s\n", joined(result.made_silent).c_str());
  if (!result.kept.empty()) std::printf("kept their annotation: %s\n", joined(result.kept).c_str());
  try {
    arbiter::PnmlReadOptions schedule;
    schedule.net_id = o.request.net_id;
    const arbiter::Net net = arbiter::readPnmlFile(o.output, schedule);
    std::printf("a schedule of %zu experts (%s); check it with ./beft net check %s\n", net.experts().size(),
                joined(net.experts()).c_str(), o.output.c_str());
    return 0;
  } catch (const arbiter::NetError& e) {
    std::printf("not yet a schedule the arbiter can run:\n");
    for (const auto& problem : e.problems()) std::printf("  %s\n", problem.c_str());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return annotate(options);
}

// beft-net-draw: draws a Petri net with Graphviz: places with their tokens,
// transitions with their experts, and, given a run's log, the marking the
// run left. Run as `./beft net draw FILE.pnml --out net.svg`.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <optional>

#include "lib/common/command_line.hpp"
#include "lib/petri/graphviz.hpp"
#include "lib/petri/net_dot.hpp"
#include "lib/petri/pnml_reader.hpp"
#include "tools/net_draw/run_marking.hpp"
#include "lib/common/whole_file.hpp"

namespace {

using namespace beft;

struct Options {
  std::string net, out, log, run_id, net_id;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Draws a Petri net: places as circles with their tokens, transitions as boxes with the\n"
      "expert they fire (silent joins and forks as bars, the tick transition doubled). With\n"
      "--log, the marking is the last one the run's arbiter published, and the experts firing\n"
      "then are highlighted. The format follows --out: .svg, .png, .pdf (Graphviz's dot draws\n"
      "them) or .dot (the graph itself).",
      "beft-net-draw");
  app.add_option("net", o.net, "PNML file")->required()->check(CLI::ExistingFile);
  app.add_option("--out,-o", o.out, "the drawing: .svg, .png, .pdf or .dot")->required();
  app.add_option("--log", o.log, "a run's LCM log: draw the last marking of its run")->check(CLI::ExistingFile);
  app.add_option("--run-id", o.run_id, "with --log: the run (hex) when the log holds several");
  app.add_option("--net-id", o.net_id, "the <net> to draw when the file holds several");
  if (const auto code = parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

std::string extensionOf(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos || path.find('/', dot) != std::string::npos ? "" : path.substr(dot + 1);
}

// Runs dot -T<format> on the graph into `out`, whole or not at all.
std::string drawInto(const std::string& graph, const std::string& format, const std::string& out) {
  const std::string partial = partialPathFor(out);
  if (std::string error = arbiter::runGraphviz(graph, format, partial); !error.empty()) return error;
  try {
    commitPartial(partial, out);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

int draw(const Options& o) {
  const std::string format = extensionOf(o.out);
  if (format != "svg" && format != "png" && format != "pdf" && format != "dot") {
    std::fprintf(stderr, "beft-net-draw: --out must end in .svg, .png, .pdf or .dot, not '%s'\n", o.out.c_str());
    return 2;
  }
  arbiter::Net net;
  try {
    arbiter::PnmlReadOptions read_options;
    read_options.schedule = false;
    read_options.net_id = o.net_id;
    net = arbiter::readPnmlFile(o.net, read_options);
  } catch (const arbiter::NetError& e) {
    for (const auto& problem : e.problems()) std::fprintf(stderr, "%s\n", problem.c_str());
    return 2;
  }
  std::optional<arbiter::ShownMarking> marking;
  if (!o.log.empty()) {
    try {
      marking = net_draw::lastMarkingOfRun(o.log, o.run_id);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "beft-net-draw: %s: %s\n", o.log.c_str(), e.what());
      return 2;
    }
    if (!marking) {
      std::fprintf(stderr, "beft-net-draw: %s holds no MARKING of the run\n", o.log.c_str());
      return 2;
    }
    for (const auto& [place, tokens] : marking->tokens)
      if (net.placeIndex(place) < 0)
        std::fprintf(stderr, "warning: the run's marking names place '%s', which this net has not (another net?)\n",
                     place.c_str());
  }
  const std::string graph = arbiter::netToDot(net, marking);
  if (format == "dot") {
    try {
      writeWholeFile(o.out, graph);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "beft-net-draw: %s\n", e.what());
      return 2;
    }
  } else if (const std::string error = drawInto(graph, format, o.out); !error.empty()) {
    std::fprintf(stderr, "beft-net-draw: %s\n", error.c_str());
    return 2;
  }
  std::printf("wrote %s (%zu places, %zu transitions%s)\n", o.out.c_str(), net.places.size(), net.transitions.size(),
              marking ? (", " + marking->caption).c_str() : "");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return draw(options);
}

// beft-figure: the paper's result figures, one command each.
//   ./beft figure 3 --out fig3.png   its planner from three starts (Fig. 3)
//   ./beft figure 4 --out fig4.png   dynamic weighting over fig4_dw (Fig. 4)
#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>

#include "lib/common/command_line.hpp"
#include "tools/figure/figure3.hpp"
#include "tools/figure/figure4.hpp"
#include "lib/common/own_bin_dir.hpp"

namespace {

using namespace beft;

struct Options {
  int figure = 0;
  std::string out, scenario;
  std::vector<std::string> starts;
  std::string goal = "26,10";
  uint64_t seed = 1;
};

std::optional<planners::Point2> parsePoint(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) return std::nullopt;
  try {
    return planners::Point2{std::stod(text.substr(0, comma)), std::stod(text.substr(comma + 1))};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Draws one of the paper's result figures.\n"
      "  3: its particle potential-field planner as printed (pf-paper: the robot traces the\n"
      "     winning particle's path) from three initial positions to one goal in one scene (the\n"
      "     ground truth of --scenario, default scenarios/yard.xml): each path as its waypoints\n"
      "     with the intended orientation at each, every particle behind them.\n"
      "  4: the dynamic weights of a fresh run of scenarios/fig4_dw.xml (every process of the\n"
      "     mission; about a minute), with the viewing direction DW computes.",
      "beft-figure");
  app.add_option("figure", o.figure, "3 or 4")->required()->check(CLI::IsMember({3, 4}));
  app.add_option("--out,-o", o.out, "the PNG to write")->required();
  app.add_option("--scenario", o.scenario, "figure 3: the scene (default scenarios/yard.xml); figure 4: the run's scenario");
  app.add_option("--start", o.starts, "figure 3: an initial position X,Y [m] (repeatable; default 2,2 3,17 27,2)");
  app.add_option("--goal", o.goal, "figure 3: the goal X,Y [m]")->capture_default_str();
  app.add_option("--seed", o.seed, "figure 3: the planner's seed")->capture_default_str();
  if (const auto code = parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

int draw(const Options& o) {
  const std::string source = BEFT_SOURCE_DIR;
  try {
    if (o.figure == 4) {
      figure::drawFigure4(ownBinDir() + "/beft-run", o.scenario.empty() ? source + "/scenarios/fig4_dw.xml" : o.scenario, o.out);
      std::printf("wrote %s\n", o.out.c_str());
      return 0;
    }
    figure::Figure3Options options;
    options.scenario_path = o.scenario.empty() ? source + "/scenarios/yard.xml" : o.scenario;
    options.seed = o.seed;
    options.out = o.out;
    const auto goal = parsePoint(o.goal);
    if (!goal) throw std::invalid_argument("--goal '" + o.goal + "' is not X,Y");
    options.goal = *goal;
    for (const auto& text : o.starts.empty() ? std::vector<std::string>{"2,2", "3,17", "27,2"} : o.starts) {
      const auto start = parsePoint(text);
      if (!start) throw std::invalid_argument("--start '" + text + "' is not X,Y");
      options.starts.push_back(*start);
    }
    const auto result = figure::drawFigure3(options);
    for (size_t i = 0; i < options.starts.size(); ++i)
      std::printf("from (%.1f, %.1f): %.2f m, %zu waypoints, %d of the particles arrived\n", options.starts[i].x,
                  options.starts[i].y, result.lengths_m[i], result.waypoints[i], result.arrived[i]);
    std::printf("wrote %s\n", o.out.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beft-figure: %s\n", e.what());
    return 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return draw(options);
}

// beft-plan: plans one query on a MovingAI map and reports the result.
#include "lib/common/command_line.hpp"
#include "planners/movingai.hpp"
#include "planners/ompl_planner.hpp"
#include "planners/path_tools.hpp"
#include "planners/planner_factory.hpp"
#include "planners/render.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

namespace bp = beft::planners;

namespace {

constexpr int kExitNoPath = 1;
constexpr int kExitBadInput = 2;

int fail(const std::string& message) {
  std::cerr << "beft-plan: error: " << message << "\n";
  return kExitBadInput;
}

std::string joined(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

// The command line and what it asks for.
struct Options {
  std::string map_file;
  int sx = 0, sy = 0, gx = 0, gy = 0;
  std::string planner_name = "pf";
  double radius = 0;
  double budget = 5.0;
  uint64_t seed = 1;
  std::vector<std::string> params;
  std::string png_file;
  bool json = false;
  bool raw = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app{
      "Plans one query on a MovingAI-format .map file: a point robot moving between cell centres "
      "(x = column, y = row, row 0 at the top), unless --radius inflates the obstacles. Prints whether "
      "it succeeded, the path length in cells and the planning time.\n"
      "Exit status: 0 path found, 1 no path found, 2 bad input (unreadable map, start or goal outside "
      "the map or blocked, unknown planner or parameter)."};
  app.add_option("MAP", o.map_file, "MovingAI .map file")->required();
  app.add_option("SX", o.sx, "start column")->required();
  app.add_option("SY", o.sy, "start row")->required();
  app.add_option("GX", o.gx, "goal column")->required();
  app.add_option("GY", o.gy, "goal row")->required();
  app.add_option("--planner", o.planner_name, "planner: " + joined(bp::plannerNames(), ", "))
      ->capture_default_str();
  app.add_option("--radius", o.radius, "robot radius [cells]: inflates the obstacles")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  app.add_option("--time-budget", o.budget, "planning deadline [s]")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--seed", o.seed, "seed of randomised planners")->capture_default_str();
  app.add_option("--param", o.params,
                 "potential-field parameter name=value, repeatable: " + joined(bp::PotentialFieldParams::names(), ", "));
  app.add_option("--png", o.png_file, "write a picture of the map, the path and (potential field) the particles");
  app.add_flag("--json", o.json, R"(print one JSON object {"planner","success","length","time_ms","path",...})");
  app.add_flag("--raw", o.raw, "return the planner's own path, not pulled taut into sparse waypoints");
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

// "" when the cell can be a start or goal on this map, else why not.
std::string checkPoint(const bp::PlanningMap& map, const std::string& map_file, const char* what, int x, int y) {
  if (!map.raw().inside(x, y)) {
    return std::string(what) + " (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
           std::to_string(map.width()) + " x " + std::to_string(map.height()) + " map " + map_file;
  }
  if (map.raw().blocked(x, y)) {
    return std::string(what) + " (" + std::to_string(x) + ", " + std::to_string(y) + ") is an obstacle cell of " +
           map_file;
  }
  if (map.inflated().blocked(x, y)) {
    return std::string(what) + " (" + std::to_string(x) + ", " + std::to_string(y) +
           ") is within the robot radius of an obstacle of " + map_file;
  }
  return "";
}

void printResult(const Options& o, const bp::Planner& planner, const bp::PlanResult& result) {
  const double time_ms = 1000.0 * result.planning_time_s;
  const bool json = o.json;
  if (json) {
    nlohmann::json out;
    out["planner"] = planner.name();
    out["success"] = result.success;
    out["length"] = result.success ? result.length() : 0.0;
    out["time_ms"] = time_ms;
    nlohmann::json path = nlohmann::json::array();
    for (const auto& p : result.path) path.push_back({p.x - 0.5, p.y - 0.5});  // cell-index coordinates
    out["path"] = path;
    if (!result.success) out["message"] = result.message;
    out["statistics"] = planner.statistics();
    std::cout << out.dump() << "\n";
  } else {
    std::printf("planner    %s\n", planner.name().c_str());
    std::printf("success    %s\n", result.success ? "yes" : "no");
    if (result.success) {
      std::printf("length     %.3f cells (%zu waypoints)\n", result.length(), result.path.size());
    } else {
      std::printf("reason     %s\n", result.message.c_str());
    }
    std::printf("time       %.2f ms (setup %.2f ms)\n", time_ms, planner.statistics().at("setup_ms"));
  }

}

// The map, the path and (potential field) the particles as a picture.
void writePicture(const Options& o, const bp::PlanningMap& map, const bp::Planner& planner, const bp::PlanResult& result,
                  bp::Point2 start, bp::Point2 goal) {
  std::vector<bp::Path> particles;
  if (const auto* pf = dynamic_cast<const bp::PotentialFieldPlanner*>(&planner)) particles = pf->particleTraces();
  const double goal_heading = result.path.size() >= 2
                                  ? std::atan2(result.path.back().y - result.path[result.path.size() - 2].y,
                                               result.path.back().x - result.path[result.path.size() - 2].x)
                                  : 0.0;
  bp::writePng(o.png_file, bp::renderPlan(map, result.path, particles, start, goal,
                                          bp::travelHeadings(result.path, goal_heading)));
}

int plan(const Options& o) {
  bp::PlannerConfig config;
  config.seed = o.seed;
  std::unique_ptr<bp::Planner> planner;
  std::shared_ptr<bp::PlanningMap> map;
  try {
    for (const auto& p : o.params) config.pf_params.push_back(bp::splitParameter(p));
    bp::seedOmpl(o.seed);
    planner = bp::makePlanner(o.planner_name, config);
    map = std::make_shared<bp::PlanningMap>(bp::loadMovingAiMap(o.map_file), o.radius);
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  for (const auto& problem : {checkPoint(*map, o.map_file, "start", o.sx, o.sy), checkPoint(*map, o.map_file, "goal", o.gx, o.gy)})
    if (!problem.empty()) return fail(problem);
  planner->setup(map);
  planner->setTighten(!o.raw);
  const bp::Point2 start = bp::cellCentre(o.sx, o.sy);
  const bp::Point2 goal = bp::cellCentre(o.gx, o.gy);
  const bp::PlanResult result = planner->solve(start, goal, bp::Deadline::after(o.budget));
  printResult(o, *planner, result);
  if (!o.png_file.empty()) {
    try {
      writePicture(o, *map, *planner, result, start, goal);
    } catch (const std::exception& e) {
      return fail(e.what());
    }
    if (!o.json) std::printf("picture    %s\n", o.png_file.c_str());
  }
  return result.success ? 0 : kExitNoPath;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return plan(options);
}

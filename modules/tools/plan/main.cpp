// beft-plan: plans one query on a MovingAI map and reports the result.
#include "movingai.hpp"
#include "ompl_planner.hpp"
#include "path_tools.hpp"
#include "planner_factory.hpp"
#include "render.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Plans one query on a MovingAI-format .map file: a point robot moving between cell centres "
      "(x = column, y = row, row 0 at the top), unless --radius inflates the obstacles. Prints whether "
      "it succeeded, the path length in cells and the planning time.\n"
      "Exit status: 0 path found, 1 no path found, 2 bad input (unreadable map, start or goal outside "
      "the map or blocked, unknown planner or parameter)."};
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
  app.add_option("MAP", map_file, "MovingAI .map file")->required();
  app.add_option("SX", sx, "start column")->required();
  app.add_option("SY", sy, "start row")->required();
  app.add_option("GX", gx, "goal column")->required();
  app.add_option("GY", gy, "goal row")->required();
  app.add_option("--planner", planner_name, "planner: " + joined(bp::plannerNames(), ", "))
      ->capture_default_str();
  app.add_option("--radius", radius, "robot radius [cells]: inflates the obstacles")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  app.add_option("--time-budget", budget, "planning deadline [s]")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--seed", seed, "seed of randomised planners")->capture_default_str();
  app.add_option("--param", params,
                 "potential-field parameter name=value, repeatable: " + joined(bp::PotentialFieldParams::names(), ", "));
  app.add_option("--png", png_file, "write a picture of the map, the path and (potential field) the particles");
  app.add_flag("--json", json, R"(print one JSON object {"planner","success","length","time_ms","path",...})");
  app.add_flag("--raw", raw, "return the planner's own path, not pulled taut into sparse waypoints");
  CLI11_PARSE(app, argc, argv);

  bp::PlannerConfig config;
  config.seed = seed;
  std::unique_ptr<bp::Planner> planner;
  try {
    for (const auto& p : params) config.pf_params.push_back(bp::splitParameter(p));
    bp::seedOmpl(seed);
    planner = bp::makePlanner(planner_name, config);
  } catch (const std::exception& e) {
    return fail(e.what());
  }

  std::shared_ptr<bp::PlanningMap> map;
  try {
    map = std::make_shared<bp::PlanningMap>(bp::loadMovingAiMap(map_file), radius);
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  const auto check_point = [&](const char* what, int x, int y) -> std::string {
    if (!map->raw().inside(x, y)) {
      return std::string(what) + " (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
             std::to_string(map->width()) + " x " + std::to_string(map->height()) + " map " + map_file;
    }
    if (map->raw().blocked(x, y)) {
      return std::string(what) + " (" + std::to_string(x) + ", " + std::to_string(y) + ") is an obstacle cell of " +
             map_file;
    }
    if (map->inflated().blocked(x, y)) {
      return std::string(what) + " (" + std::to_string(x) + ", " + std::to_string(y) +
             ") is within the robot radius of an obstacle of " + map_file;
    }
    return "";
  };
  for (const auto& problem : {check_point("start", sx, sy), check_point("goal", gx, gy)}) {
    if (!problem.empty()) return fail(problem);
  }

  planner->setup(map);
  planner->setTighten(!raw);
  const bp::Point2 start = bp::cellCentre(sx, sy);
  const bp::Point2 goal = bp::cellCentre(gx, gy);
  const bp::PlanResult result = planner->solve(start, goal, bp::Deadline::after(budget));
  const double time_ms = 1000.0 * result.planning_time_s;

  if (json) {
    nlohmann::json out;
    out["planner"] = planner->name();
    out["success"] = result.success;
    out["length"] = result.success ? result.length() : 0.0;
    out["time_ms"] = time_ms;
    nlohmann::json path = nlohmann::json::array();
    for (const auto& p : result.path) path.push_back({p.x - 0.5, p.y - 0.5});  // cell-index coordinates
    out["path"] = path;
    if (!result.success) out["message"] = result.message;
    out["statistics"] = planner->statistics();
    std::cout << out.dump() << "\n";
  } else {
    std::printf("planner    %s\n", planner->name().c_str());
    std::printf("success    %s\n", result.success ? "yes" : "no");
    if (result.success) {
      std::printf("length     %.3f cells (%zu waypoints)\n", result.length(), result.path.size());
    } else {
      std::printf("reason     %s\n", result.message.c_str());
    }
    std::printf("time       %.2f ms (setup %.2f ms)\n", time_ms, planner->statistics().at("setup_ms"));
  }

  if (!png_file.empty()) {
    std::vector<bp::Path> particles;
    if (const auto* pf = dynamic_cast<const bp::PotentialFieldPlanner*>(planner.get())) {
      particles = pf->particleTraces();
    }
    try {
      const double goal_heading = result.path.size() >= 2
                                      ? std::atan2(result.path.back().y - result.path[result.path.size() - 2].y,
                                                   result.path.back().x - result.path[result.path.size() - 2].x)
                                      : 0.0;
      bp::writePng(png_file, bp::renderPlan(*map, result.path, particles, start, goal,
                                            bp::travelHeadings(result.path, goal_heading)));
    } catch (const std::exception& e) {
      return fail(e.what());
    }
    if (!json) std::printf("picture    %s\n", png_file.c_str());
  }
  return result.success ? 0 : kExitNoPath;
}

#include "tools/experiment/episode_run.hpp"

#include <filesystem>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>

#include "tools/experiment/json_fields.hpp"
#include "tools/experiment/scenes.hpp"

namespace beft::experiment {
namespace fs = std::filesystem;

std::string episodeFolder(const std::string& out_dir, const Episode& episode) {
  return (fs::path(out_dir) / "episodes" / episode.id).string();
}

std::vector<std::string> runCommand(const Experiment& experiment, const Episode& episode, const std::string& folder,
                                    const std::string& bin_dir) {
  std::string scene_file;
  for (const auto& scene : experiment.scenes)
    if (scene.name == *episode.value(kScene)) scene_file = scene.file;
  std::vector<std::string> command = {bin_dir + "/beft-run", scene_file, "--out", folder};
  if (experiment.max_ticks > 0) command.insert(command.end(), {"--max-ticks", std::to_string(experiment.max_ticks)});
  for (const auto& [factor, value] : episode.values) {
    if (factor == kScene) continue;
    if (factor.rfind("set:", 0) == 0)
      command.insert(command.end(), {"--set", factor.substr(4) + "=" + value});
    else if (factor == "net")
      command.insert(command.end(), {"--net", (fs::path(experiment.base_dir) / value).lexically_normal().string()});
    else
      command.insert(command.end(), {"--" + factor, value});
  }
  return command;
}

std::vector<std::string> recordedCommand(const std::vector<std::string>& command, const std::string& out_dir) {
  std::vector<std::string> recorded(command.begin() + (command.empty() ? 0 : 1), command.end());
  for (auto& arg : recorded)
    if (arg.rfind(out_dir, 0) == 0) arg = "OUT" + arg.substr(out_dir.size());
  return recorded;
}

namespace {

// The report's simulated time [s]; nullopt when report.json does not read.
std::optional<double> reportedSimulatedS(const std::string& folder) {
  std::ifstream in(fs::path(folder) / "report.json");
  if (!in) return std::nullopt;
  const auto report = nlohmann::json::parse(in, nullptr, false);
  if (report.is_discarded() || !report.is_object()) return std::nullopt;
  const auto time = report.find("sim_time_s");
  return time != report.end() && time->is_number() ? time->get<double>() : 0.0;
}

}  // namespace

EpisodeState readEpisodeState(const std::string& folder) {
  std::ifstream in(fs::path(folder) / kEpisodeFile);
  if (!in) return {};
  const auto json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded() || !json.is_object()) return {};
  EpisodeState state;
  state.status = valueOr(json, "status", std::string()) == "done" ? Status::done : Status::failed;
  state.exit_code = valueOr(json, "exit_code", 0);
  state.wall_s = valueOr(json, "wall_s", 0.0);
  state.simulated_s = valueOr(json, "simulated_s", 0.0);
  state.reason = valueOr(json, "reason", std::string());
  state.command = stringsOr(json, "command");
  state.log_removed = valueOr(json, "log", std::string()).rfind("removed", 0) == 0;
  if (state.status == Status::done && !reportedSimulatedS(folder)) return {};
  return state;
}

void writeEpisodeState(const std::string& folder, const EpisodeState& state) {
  const nlohmann::json json = {{"status", state.status == Status::done ? "done" : "failed"},
                               {"exit_code", state.exit_code},
                               {"wall_s", state.wall_s},
                               {"simulated_s", state.simulated_s},
                               {"reason", state.reason},
                               {"command", state.command},
                               {"log", state.log_removed ? "removed: the episode succeeded; its command, run again, "
                                                           "writes the same data messages"
                                                         : kRunLog}};
  const fs::path file = fs::path(folder) / kEpisodeFile, partial = fs::path(folder) / "episode.json.partial";
  std::ofstream(partial) << json.dump(2) << "\n";
  fs::rename(partial, file);  // whole or not at all
}

EpisodeState finishedState(const std::string& folder, int exit_code, double wall_s) {
  EpisodeState state;
  state.status = Status::done;
  state.exit_code = exit_code;
  state.wall_s = wall_s;
  const auto simulated_s = reportedSimulatedS(folder);
  if (exit_code == 0 && simulated_s) {
    state.simulated_s = *simulated_s;
    return state;
  }
  state.status = Status::failed;
  state.reason = lastLineOf((fs::path(folder) / kRunOutput).string(), "error");
  if (state.reason.empty()) state.reason = lastLineOf((fs::path(folder) / "processes.log").string(), "error");
  if (state.reason.empty())
    state.reason = exit_code == 0 ? "no readable report.json" : "beft-run exited with code " + std::to_string(exit_code);
  return state;
}

}  // namespace beft::experiment

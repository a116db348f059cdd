#include "tools/experiment/log_policy.hpp"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tools/experiment/json_fields.hpp"

namespace beft::experiment {
namespace fs = std::filesystem;

std::optional<KeepLogs> keepLogsNamed(const std::string& name) {
  if (name == "unsuccessful") return KeepLogs::unsuccessful;
  if (name == "all") return KeepLogs::all;
  return std::nullopt;
}

std::string nameOf(KeepLogs keep) { return keep == KeepLogs::all ? "all" : "unsuccessful"; }

bool succeeded(const std::string& folder, const EpisodeState& state) {
  if (state.status != Status::done) return false;
  std::ifstream in(fs::path(folder) / "report.json");
  const auto report = nlohmann::json::parse(in, nullptr, false);
  // Both must be there: a report without its collisions is no success.
  return valueOr(report, "completed", false) && valueOr(report, "collisions", int64_t{-1}) == 0;
}

bool applyLogPolicy(const std::string& folder, const EpisodeState& state, KeepLogs keep) {
  if (keep == KeepLogs::all || !succeeded(folder, state)) return false;
  std::error_code error;
  return fs::remove(fs::path(folder) / kRunLog, error) && !error;
}

}  // namespace beft::experiment

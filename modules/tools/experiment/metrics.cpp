#include "tools/experiment/metrics.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

#include "tools/experiment/json_fields.hpp"
#include "tools/experiment/statistics.hpp"

namespace beft::experiment {
namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

double meanHeardError(const nlohmann::json& heard) {
  if (!heard.is_array() || heard.empty()) return kNone;
  double sum = 0;
  for (const auto& h : heard) sum += valueOr(h, "error_m", 0.0);
  return sum / heard.size();
}

std::vector<double> foundTimes(const nlohmann::json& victims) {
  std::vector<double> times;
  if (victims.is_array())
    for (const auto& v : victims) times.push_back(valueOr(v, "found_at_s", 0.0));
  return times;
}

// The found persons' path efficiencies, in report order (those that have one).
std::vector<double> pathEfficiencies(const nlohmann::json& victims) {
  std::vector<double> values;
  if (victims.is_array())
    for (const auto& v : victims)
      if (v.is_object() && v.contains("path_efficiency") && v["path_efficiency"].is_number())
        values.push_back(v["path_efficiency"].get<double>());
  return values;
}

int count(const nlohmann::json& report, const char* list) {
  return report.contains(list) && report[list].is_array() ? static_cast<int>(report[list].size()) : 0;
}

}  // namespace

std::optional<EpisodeMetrics> readMetrics(const std::string& report_file) {
  std::ifstream in(report_file);
  const auto report = nlohmann::json::parse(in, nullptr, false);
  if (report.is_discarded() || !report.is_object()) return std::nullopt;
  EpisodeMetrics m;
  m.completed = valueOr(report, "completed", false);
  m.persons_found = count(report, "victims");
  m.persons_present = valueOr(report, "persons", 0);
  m.false_alarms = count(report, "false_alarms");
  m.falsified = count(report, "falsified");
  m.unsettled = count(report, "unsettled");
  m.end_reason = valueOr(report, "end_reason", std::string());
  m.collisions = valueOr(report, "collisions", 0);
  m.path_length_m = valueOr(report, "path_length_m", 0.0);
  m.sim_time_s = valueOr(report, "sim_time_s", 0.0);
  m.wall_time_s = valueOr(report, "wall_time_s", 0.0);
  m.heard_error_mean_m = meanHeardError(listOr(report, "heard"));
  const nlohmann::json victims = listOr(report, "victims");
  const auto times = foundTimes(victims);
  m.found_at_s = times;
  m.time_to_find_first_s = quantile(times, 0.0);
  m.time_to_find_median_s = quantile(times, 0.5);
  m.path_efficiency_mean = valueOr(report, "path_efficiency_mean", kNone);
  m.path_efficiency = pathEfficiencies(victims);
  return m;
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csvNumber(double value) {
  if (!std::isfinite(value)) return "";
  char text[48];
  std::snprintf(text, sizeof(text), "%.3f", value);
  return text;
}

namespace {

const char* const kMetricsHeader =
    "completed,persons_found,persons_present,false_alarms,falsified,unsettled,collisions,path_length_m,sim_time_s,"
    "wall_time_s,heard_error_mean_m,time_to_find_first_s,time_to_find_median_s,path_efficiency_mean,end_reason";

std::string metricsFields(const EpisodeMetrics& m) {
  return std::string(m.completed ? "1" : "0") + "," + std::to_string(m.persons_found) + "," +
         std::to_string(m.persons_present) + "," + std::to_string(m.false_alarms) + "," +
         std::to_string(m.falsified) + "," + std::to_string(m.unsettled) + "," + std::to_string(m.collisions) + "," +
         csvNumber(m.path_length_m) + "," + csvNumber(m.sim_time_s) + "," + csvNumber(m.wall_time_s) + "," +
         csvNumber(m.heard_error_mean_m) + "," + csvNumber(m.time_to_find_first_s) + "," +
         csvNumber(m.time_to_find_median_s) + "," + csvNumber(m.path_efficiency_mean) + "," + csvField(m.end_reason);
}

// The empty fields of an episode without measures, one per column.
std::string noMetrics() {
  const std::string header = kMetricsHeader;
  return std::string(std::count(header.begin(), header.end(), ','), ',');
}

const char* statusName(Status status) {
  return status == Status::done ? "done" : status == Status::failed ? "failed" : "missing";
}

}  // namespace

void writeEpisodesCsv(const Experiment& experiment, const std::vector<EpisodeResult>& results, std::ostream& out) {
  out << "episode,scene";
  for (const auto& factor : experiment.factors) out << "," << csvField(factor.name);
  out << ",status,reason," << kMetricsHeader << "\n";
  for (const auto& r : results) {
    out << csvField(r.episode.id);
    for (const auto& [factor, value] : r.episode.values) out << "," << csvField(value);
    out << "," << statusName(r.state.status) << "," << csvField(r.state.reason) << ",";
    out << (r.metrics ? metricsFields(*r.metrics) : noMetrics()) << "\n";
  }
}

}  // namespace beft::experiment

#include "lib/report/report_json.hpp"

#include <cmath>
#include <iomanip>

namespace beft::report {
namespace {

// Rounded for reading; the log keeps the exact values.
double rounded(double value, int decimals = 3) {
  const double scale = std::pow(10.0, decimals);
  return std::round(value * scale) / scale;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text.empty() ? "none" : text;
}

// "tasks 120, vision 118": who refused how many messages without a valid tag.
std::string refusedByProcess(const RunReport& report) {
  std::vector<std::string> items;
  for (const auto& [process, count] : report.unauthenticated_messages)
    items.push_back(process + " " + std::to_string(count));
  return joined(items);
}

// A victim found; its path efficiency only when it was computed.
nlohmann::json victimJson(const VictimEntry& v) {
  nlohmann::json json = {{"object", v.object},
                         {"hypothesis", v.hypothesis},
                         {"x", rounded(v.x)},
                         {"y", rounded(v.y)},
                         {"true_x", rounded(v.true_x)},
                         {"true_y", rounded(v.true_y)},
                         {"error_m", rounded(v.error_m)},
                         {"placed_at_s", rounded(v.placed_at_s)},
                         {"confidence", rounded(v.confidence)},
                         {"verified", v.verified},
                         {"found_at_s", rounded(v.found_at_s)}};
  if (v.shortest_path_m) json["shortest_path_m"] = rounded(*v.shortest_path_m);
  if (v.driven_m) json["driven_m"] = rounded(*v.driven_m);
  if (v.path_efficiency) json["path_efficiency"] = rounded(*v.path_efficiency);
  return json;
}

}  // namespace

nlohmann::json toJson(const RunReport& report) {
  nlohmann::json json;
  json["scenario"] = report.scenario;
  json["log"] = report.log_path;
  json["completed"] = report.completed;
  json["sim_time_s"] = rounded(report.sim_time_s);
  json["wall_time_s"] = rounded(report.wall_time_s, 4);
  json["wall_time_source"] = report.wall_time_measured ? "runner" : "log timestamps";
  json["ticking_time_s"] = rounded(report.ticking_time_s, 4);
  json["ticks"] = report.ticks;
  json["ticks_per_s"] = rounded(report.ticks_per_s, 1);
  json["realtime_factor"] = rounded(report.realtime_factor, 1);
  json["overall_realtime_factor"] = rounded(report.overall_realtime_factor, 1);
  json["path_length_m"] = rounded(report.path_length_m);
  json["collisions"] = report.collisions;
  json["persons"] = report.persons;
  json["person_confidence_threshold"] = report.person_confidence;
  json["victims"] = nlohmann::json::array();
  for (const auto& v : report.victims) json["victims"].push_back(victimJson(v));
  if (report.path_efficiency_mean) json["path_efficiency_mean"] = rounded(*report.path_efficiency_mean);
  json["falsified"] = nlohmann::json::array();
  for (const auto& f : report.falsified)
    json["falsified"].push_back({{"object", f.object},
                                 {"x", rounded(f.x)},
                                 {"y", rounded(f.y)},
                                 {"heard_as", f.heard_as},
                                 {"seen_as", f.seen_as},
                                 {"settled_at_s", rounded(f.settled_at_s)}});
  json["missed"] = report.missed;
  json["heard"] = nlohmann::json::array();  // the audio expert's last estimate of each sounding object
  for (const auto& h : report.heard)
    json["heard"].push_back({{"object", h.object},
                             {"x", rounded(h.x)},
                             {"y", rounded(h.y)},
                             {"true_x", rounded(h.true_x)},
                             {"true_y", rounded(h.true_y)},
                             {"error_m", rounded(h.error_m)},
                             {"at_s", rounded(h.at_s)}});
  json["false_alarms"] = nlohmann::json::array();
  for (const auto& a : report.false_alarms)
    json["false_alarms"].push_back({{"hypothesis", a.hypothesis},
                                    {"x", rounded(a.x)},
                                    {"y", rounded(a.y)},
                                    {"confidence", rounded(a.confidence)},
                                    {"reason", a.reason}});
  json["hypotheses"] = report.hypotheses;
  json["unsettled"] = report.unsettled;
  json["unsettled_why"] = nlohmann::json::object();
  for (const auto& [object, why] : report.unsettled_why) json["unsettled_why"][object] = why;
  json["end_reason"] = report.end_reason;
  json["rejected_messages"] = nlohmann::json::object();
  int64_t rejected_total = 0;
  for (const auto& [channel, count] : report.rejected_messages) {
    json["rejected_messages"][channel] = count;
    rejected_total += count;
  }
  json["rejected_total"] = rejected_total;
  json["log_damage"] = report.log_damage;
  json["log_complete"] = report.log_complete;
  json["log_messages_lost"] = report.log_messages_lost;
  json["log_messages_repaired"] = report.log_messages_repaired;
  json["other_run_messages"] = report.other_run_messages;
  // What the processes of a keyed run refused for want of a valid tag, as each told it.
  json["unauthenticated_messages"] = nlohmann::json::object();
  for (const auto& [process, count] : report.unauthenticated_messages)
    json["unauthenticated_messages"][process] = count;
  json["unauthenticated_total"] = unauthenticatedTotal(report);
  return json;
}

void printSummary(const RunReport& report, std::ostream& out) {
  const auto flags = out.flags();
  out << std::fixed << std::setprecision(2);
  out << "Run report: " << (report.scenario.empty() ? "(unnamed scenario)" : report.scenario) << "\n";
  out << "  completed:   " << (report.completed ? "yes" : "no") << " (" << report.victims.size() << " of "
      << report.persons << " persons found, " << report.unsettled.size() << " of " << report.hypotheses
      << " hypotheses unsettled)\n";
  out << "  time:        " << std::setprecision(1) << report.sim_time_s << " s simulated, " << report.ticks
      << " ticks";
  if (report.ticking_time_s > 0)
    out << " in " << std::setprecision(2) << report.ticking_time_s << " s of lockstep loop";
  if (report.ticks_per_s > 0)
    out << ": " << std::setprecision(0) << report.ticks_per_s << " ticks/s, " << std::setprecision(1)
        << report.realtime_factor << "x real time";
  out << "\n" << std::setprecision(2);
  if (report.wall_time_s > 0)
    out << "  wall:        " << report.wall_time_s << " s in all, every process started and stopped ("
        << std::setprecision(1) << report.overall_realtime_factor << "x real time)\n" << std::setprecision(2);
  out << "  robot:       path " << report.path_length_m << " m, " << report.collisions << " collisions\n";
  for (const auto& v : report.victims)
    out << "  victim:      " << v.object << " at (" << v.x << ", " << v.y << "), error " << v.error_m
        << " m, confidence " << v.confidence << (v.verified ? ", verified" : ", not verified")
        << ", found at " << std::setprecision(1) << v.found_at_s << " s\n"
        << std::setprecision(2);
  for (const auto& f : report.falsified)
    out << "  falsified:   " << f.object << " at (" << f.x << ", " << f.y << "): heard as '" << f.heard_as
        << "', seen as '" << f.seen_as << "'\n";
  for (const auto& a : report.false_alarms)
    out << "  false alarm: " << a.hypothesis << " at (" << a.x << ", " << a.y << "): " << a.reason << "\n";
  out << "  missed:      " << joined(report.missed) << "\n";
  if (!report.unsettled.empty()) out << "  unsettled:   " << joined(report.unsettled) << "\n";
  for (const auto& [object, why] : report.unsettled_why) out << "    " << object << ": " << why << "\n";
  if (!report.end_reason.empty()) out << "  ended:       " << report.end_reason << "\n";
  if (const int64_t refused = unauthenticatedTotal(report); refused > 0)
    out << "  refused:     " << refused << " message(s) without a valid tag of the run's key ("
        << refusedByProcess(report) << ")\n";
  out.flags(flags);
}

}  // namespace beft::report

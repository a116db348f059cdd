#include "tools/report/unsettled_reasons.hpp"

#include <cstdio>
#include <string>

#include "lib/scenario/sight_lines.hpp"

namespace beft::report {

namespace {

// What the end reason says of `id` ("; ID: why" up to the next "; "), or "".
std::string saidOf(const std::string& end_reason, const std::string& id) {
  const std::string key = "; " + id + ": ";
  const auto at = end_reason.find(key);
  if (at == std::string::npos) return "";
  const auto from = at + key.size();
  const auto to = end_reason.find("; ", from);
  return end_reason.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

std::string at(const scenario::Place& place) {
  char text[64];
  std::snprintf(text, sizeof(text), "(%.1f, %.1f)", place.x, place.y);
  return text;
}

}  // namespace

void explainUnsettled(const scenario::Scenario& scenario, RunReport& report) {
  if (report.unsettled.empty()) return;
  const scenario::SightLines lines(scenario);
  for (const std::string& id : report.unsettled) {
    std::string why;
    if (const scenario::Object* object = scenario.findObject(id)) {
      const auto place = lines.placeThatSees(*object);
      why = place ? "seen on the ground truth from " + at(*place) + ", a place the robot can reach"
                  : "no place the robot can reach sees it on the ground truth (within 1.5-6 m, camera at 1.6 m)";
    } else {
      why = "no object of the scenario has this id";
    }
    const std::string said = saidOf(report.end_reason, id);
    if (!said.empty()) why += "; the exploration: " + said;
    report.unsettled_why[id] = why;
  }
}

}  // namespace beft::report

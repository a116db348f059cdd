#include "tools/bench_faults/outcome.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "lib/wire/run_identity.hpp"

namespace beft::bench {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

std::string lineAfter(const std::string& text, const std::string& prefix) {
  const auto at = text.find(prefix);
  return at == std::string::npos ? "" : text.substr(at + prefix.size(), text.find('\n', at) - at - prefix.size());
}

int64_t runIdIn(const std::string& output) {
  const std::string started = lineAfter(output, "[launch] started ");
  const auto at = started.find(" as run ");
  if (at == std::string::npos) return 0;
  try {
    return wire::parseRunId(started.substr(at + 8, started.find_first_of(" ;,", at + 8) - at - 8));
  } catch (const std::exception&) {
    return 0;
  }
}

void readRun(const std::string& report_json, const std::string& processes_output, Outcome& outcome) {
  try {
    const auto report = nlohmann::json::parse(readFile(report_json));
    outcome.completed = report.value("completed", false);
    outcome.rejected = report.value("rejected_total", 0LL);
    outcome.other_run = report.value("other_run_messages", 0LL);
    outcome.untagged = report.value("unauthenticated_total", 0LL);
    outcome.ticks_per_s = report.value("ticks_per_s", 0.0);
    outcome.log_complete = report.value("log_complete", false);
    outcome.repairs_served = report.value("log_messages_repaired", -1LL);
    outcome.lost = report.value("log_messages_lost", -1LL);
  } catch (const std::exception&) {
  }
  // The recorder says "loss repair: N message(s) missed at first, ..." when it missed any.
  const std::string repair = lineAfter(processes_output, "loss repair: ");
  // Without it: none missed if none was repaired or lost, else not said (the recorder did not finish).
  if (!repair.empty()) outcome.repairs_asked = std::strtoll(repair.c_str(), nullptr, 10);
  else if (outcome.repairs_served == 0 && outcome.lost == 0) outcome.repairs_asked = 0;
  for (auto at = processes_output.find(": restarting ("); at != std::string::npos;
       at = processes_output.find(": restarting (", at + 1))
    ++outcome.restarts;
}

namespace {

std::string count(long long value) { return value < 0 ? "-" : std::to_string(value); }

}  // namespace

void printOutcomes(const std::vector<Outcome>& outcomes) {
  // The comparison last: a difference is a long text.
  std::printf("%-24s %-9s %8s %9s %8s %8s %6s %8s %5s %8s %7s  %s\n", "yard.xml", "completed", "rejected", "other run",
              "untagged", "restarts", "missed", "repaired", "lost", "log full", "ticks/s",
              "data messages as the clean run");
  for (const auto& o : outcomes) {
    if (!o.skipped.empty()) {
      std::printf("%-24s %s\n", o.name.c_str(), o.skipped.c_str());
      continue;
    }
    std::printf("%-24s %-9s %8lld %9lld %8lld %8lld %6s %8s %5s %8s %7.0f  %s\n", o.name.c_str(),
                o.completed ? "yes" : "no", o.rejected, o.other_run, o.untagged, o.restarts,
                count(o.repairs_asked).c_str(), count(o.repairs_served).c_str(), count(o.lost).c_str(),
                o.log_complete ? "yes" : "no", o.ticks_per_s, o.identical.c_str());
  }
}

}  // namespace beft::bench

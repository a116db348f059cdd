#include "lib/wire/run_discovery.hpp"

#include <chrono>

#include <lcm/lcm-cpp.hpp>

#include "lib/common/channels.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::wire {

namespace {

void onHeartbeat(const lcm::ReceiveBuffer*, const std::string& channel, std::set<int64_t>* runs) {
  runs->insert(splitRunChannel(channel).run_id);
}

}  // namespace

std::set<int64_t> runsHeard(lcm::LCM& lcm, double seconds) {
  std::set<int64_t> runs;
  auto* subscription =
      lcm.subscribeFunction(std::string(channels::kHeartbeat.name) + "(@[0-9a-f]+)?", &onHeartbeat, &runs);
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (runs.empty()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now());
    if (left.count() <= 0 || lcm.handleTimeout(static_cast<int>(left.count())) < 0) break;
  }
  // A little longer to hear a second run's heartbeat too.
  const auto settle = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
  while (!runs.empty() && std::chrono::steady_clock::now() < settle) lcm.handleTimeout(100);
  lcm.unsubscribe(subscription);
  return runs;
}

std::string adoptTheRunHeard(lcm::LCM& lcm, double seconds) {
  if (runId() != 0) return "";
  const std::set<int64_t> runs = runsHeard(lcm, seconds);
  if (runs.size() == 1) {
    setRunId(*runs.begin());
    return "";
  }
  if (runs.empty()) return "";  // nothing heard: the plain channel names, as a run without id uses
  std::string list;
  for (int64_t id : runs) list += (list.empty() ? "" : ", ") + runIdText(id);
  return "several runs share this LCM URL (" + list + "): say which with --run-id";
}

}  // namespace beft::wire

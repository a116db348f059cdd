#include "lib/launch/launch_identity.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

#include "lib/launch/run_adoption.hpp"
#include "lib/transport/message_key.hpp"

namespace beft::launch {

namespace {

int64_t wallClock_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::string arbiterHost(const LaunchSpec& spec) {
  for (const auto& process : spec.processes)
    if (process.is_arbiter) return process.host;
  return "";
}

LaunchIdentity adopted(const LaunchSpec& spec, const LaunchIdentityRequest& request, int64_t description) {
  char timeout[32];
  std::snprintf(timeout, sizeof timeout, "%g s", request.join_timeout_s);
  if (request.say)
    request.say("the arbiter runs on host '" + arbiterHost(spec) + "', not here: waiting up to " + timeout +
                " for its run to announce itself on " + request.lcm_url);
  lcm::LCM lcm(request.lcm_url);
  if (!lcm.good()) throw LaunchError("cannot open the LCM URL " + request.lcm_url + " to hear the run's beacons");
  AdoptionOptions options;
  options.timeout_s = request.join_timeout_s;
  options.say = request.say;
  options.key = transport::processKey();  // set from --key or BEFT_KEY_FILE (run_key.hpp)
  const AnnouncedRun run = adoptAnnouncedRun(lcm, description, options);
  if (request.say)
    request.say("joining " + describeAnnouncedRun(run, wallClock_us()) +
                ", announced for this launch file and arguments");
  return {run.run_id, {description, run.started_utime}};
}

}  // namespace

bool drawsTheRunId(const LaunchSpec& spec, const std::string& host) {
  for (const auto& process : spec.processes)
    if (process.is_arbiter) return process.host == host;
  return true;
}

LaunchIdentity identifyLaunch(const LaunchSpec& spec, const LaunchIdentityRequest& request) {
  const int64_t description = launchDescriptionOf(request.launch_file, spec.args);
  const bool draws = drawsTheRunId(spec, request.host);
  if (!request.given_run_id.empty()) {
    int64_t id = 0;
    try {
      id = wire::parseRunId(request.given_run_id);
    } catch (const std::invalid_argument& e) {
      throw LaunchError(std::string("--run-id: ") + e.what());
    }
    return {id, {description, draws ? wallClock_us() : 0}};  // 0: the plain channel names, as before run ids
  }
  if (draws) return {wire::freshRunId(), {description, wallClock_us()}};
  return adopted(spec, request, description);
}

}  // namespace beft::launch

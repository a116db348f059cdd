// Which run a launch is. Every launch is a run of its own: the id given with
// --run-id (0: none, the plain channel names); else, when this host runs the
// arbiter (or would, started by hand with --except; or the launch has none),
// a fresh random one; else, on the other hosts of a distributed run, the one
// the arbiter announces for the same launch file and arguments
// (run_adoption.hpp). So yesterday's run of a scenario, its log replayed on
// the URL, is never taken for today's.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "lib/launch/launch_file.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::launch {

struct LaunchIdentityRequest {
  std::string launch_file;    // as given: its name is part of the description
  std::string given_run_id;   // --run-id (hex), "" for none
  std::string host = "local"; // this machine's host label
  std::string lcm_url;
  double join_timeout_s = 30;                   // how long to wait for the arbiter's beacon
  std::function<void(const std::string&)> say;  // what the launcher prints, one line each
};

struct LaunchIdentity {
  int64_t run_id = 0;
  wire::RunOrigin origin;  // for the arbiter's beacons (SupervisorOptions::run_origin)
};

// True when this host draws the run's id: the arbiter is placed on it, or
// the launch has no arbiter.
bool drawsTheRunId(const LaunchSpec& spec, const std::string& host);

// Throws LaunchError: a bad --run-id, no run to join, several to choose from.
LaunchIdentity identifyLaunch(const LaunchSpec& spec, const LaunchIdentityRequest& request);

}  // namespace beft::launch

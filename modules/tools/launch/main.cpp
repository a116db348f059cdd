// beft-launch: start the processes of a launch file (./beft launch FILE).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lib/launch/camera_sampling.hpp"
#include "lib/common/command_line.hpp"
#include "lib/launch/free_port.hpp"
#include "lib/launch/launch_file.hpp"
#include "lib/launch/launch_identity.hpp"
#include "lib/launch/run_key.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/common/own_bin_dir.hpp"
#include "lib/launch/supervisor.hpp"

namespace {

struct Options {
  std::string file, lcm_url, record, run_id, key_file;
  std::string record_camera = "all";
  std::vector<std::string> sets, except;
  std::string host = "local";
  double join_timeout_s = 30;
  bool new_port = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Starts the processes listed in a launch file (scenarios/launch/*.xml), prefixes each "
      "line they print with their name, restarts them per their policy, and stops them all on "
      "Ctrl-C or when the arbiter ends the run.\n\nDebugging one module: --except vision starts "
      "all but vision and prints the command line to start it by hand (e.g. under gdb); the "
      "arbiter waits for its heartbeat.",
      "beft-launch");
  app.add_option("file", o.file, "launch file")->required()->check(CLI::ExistingFile);
  app.add_option("--set", o.sets, "NAME=VALUE for an <arg> of the file (repeatable)");
  app.add_option("--except", o.except, "do not start this process (repeatable)");
  app.add_option("--host", o.host, "host label of this machine: only its processes start")->capture_default_str();
  app.add_option("--lcm-url", o.lcm_url, "LCM URL for every process (default: BEFT_LCM_URL or host-local)");
  app.add_flag("--new-port", o.new_port, "use a free UDP port of its own instead of the default URL");
  auto* record = app.add_option("--record", o.record, "record the run's LCM traffic to this log file");
  app.add_option("--record-camera", o.record_camera,
                 "camera frames kept in the log: all, none, or every:N (those of ticks 0, N, 2N, ...)")
      ->capture_default_str()
      ->needs(record)
      ->check(beft::record::CameraSampling::problemWith);
  app.add_option("--run-id", o.run_id,
                 "the run's id (hex), stamped on every message; 0: none, the plain channel names. Default: a fresh "
                 "random id where the arbiter runs; on another --host, the id the arbiter announces on the URL for "
                 "the same launch file and arguments (not --host)");
  app.add_option("--key", o.key_file,
                 "the run's key (./beft key new FILE; default: BEFT_KEY_FILE): every process tags its messages with "
                 "it and refuses those without a valid tag (another program's, a replayed log's); every host "
                 "of the run needs the same key file")
      ->check(CLI::ExistingFile);
  app.add_option("--join-timeout", o.join_timeout_s,
                 "on a host without the arbiter: seconds to wait for the arbiter's run to announce itself")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

// The URL given, a free port of its own (--new-port), or the default; "" if no port is free.
std::string lcmUrlOf(const Options& o) {
  if (!o.lcm_url.empty()) return o.lcm_url;
  if (!o.new_port) return beft::defaultLcmUrl();
  const int port = beft::launch::findFreeUdpPort();
  return port < 0 ? "" : beft::lcmUrlForPort(port);
}

beft::launch::LaunchIdentityRequest identityRequest(const Options& o, const std::string& lcm_url) {
  beft::launch::LaunchIdentityRequest request;
  request.launch_file = o.file;
  request.given_run_id = o.run_id;
  request.host = o.host;
  request.lcm_url = lcm_url;
  request.join_timeout_s = o.join_timeout_s;
  request.say = [](const std::string& line) {
    std::printf("[launch] %s\n", line.c_str());
    std::fflush(stdout);
  };
  return request;
}

int launch(const Options& o) {
  beft::launch::SupervisorOptions options;
  options.host = o.host;
  options.except = {o.except.begin(), o.except.end()};
  options.bin_dir = beft::ownBinDir();
  options.record_log = o.record;
  options.record_camera = o.record_camera;
  options.lcm_url = lcmUrlOf(o);
  if (options.lcm_url.empty()) {
    std::fprintf(stderr, "[launch] error: no free UDP port\n");
    return 1;
  }
  try {
    auto overrides = beft::launch::parseSettings(o.sets);
    overrides["lcm_url"] = options.lcm_url;
    options.key_file = beft::launch::runKeyFile(o.key_file);
    const auto spec = beft::launch::loadLaunchFile(o.file, overrides);
    const auto identity = beft::launch::identifyLaunch(spec, identityRequest(o, options.lcm_url));
    options.run_id = identity.run_id;
    options.run_origin = identity.origin;
    const auto outcome = beft::launch::supervise(spec, options);
    std::printf("[launch] %s\n", outcome.message.c_str());
    if (outcome.interrupted) return 130;
    if (outcome.arbiter_ran) return outcome.arbiter_exit_code == 0 ? 0 : 1;
    return 0;
  } catch (const std::exception& e) {  // LaunchError: a bad file, --run-id or key, no run to join
    std::fprintf(stderr, "[launch] error: %s\n", e.what());
    return 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return launch(options);
}

// beft-launch: start the processes of a launch file (./beft launch FILE).
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <climits>
#include <cstdio>

#include "free_port.hpp"
#include "lcm_url.hpp"
#include "own_bin_dir.hpp"
#include "supervisor.hpp"

int main(int argc, char** argv) {
  std::string file, lcm_url, record;
  std::vector<std::string> sets, except;
  std::string host = "local";
  bool new_port = false;
  CLI::App app(
      "Starts the processes listed in a launch file (scenarios/launch/*.xml), prefixes each "
      "line they print with their name, restarts them per their policy, and stops them all on "
      "Ctrl-C or when the arbiter ends the run.\n\nDebugging one module: --except vision starts "
      "all but vision and prints the command line to start it by hand (e.g. under gdb); the "
      "arbiter waits for its heartbeat.",
      "beft-launch");
  app.add_option("file", file, "launch file")->required()->check(CLI::ExistingFile);
  app.add_option("--set", sets, "NAME=VALUE for an <arg> of the file (repeatable)");
  app.add_option("--except", except, "do not start this process (repeatable)");
  app.add_option("--host", host, "host label of this machine: only its processes start")->capture_default_str();
  app.add_option("--lcm-url", lcm_url, "LCM URL for every process (default: BEFT_LCM_URL or host-local)");
  app.add_flag("--new-port", new_port, "use a free UDP port of its own instead of the default URL");
  app.add_option("--record", record, "record the run's LCM traffic to this log file");
  CLI11_PARSE(app, argc, argv);

  beft::launch::SupervisorOptions options;
  options.host = host;
  options.except = {except.begin(), except.end()};
  options.bin_dir = beft::ownBinDir();
  options.record_log = record;
  if (lcm_url.empty()) {
    if (new_port) {
      const int port = beft::launch::findFreeUdpPort();
      if (port < 0) {
        std::fprintf(stderr, "[launch] error: no free UDP port\n");
        return 1;
      }
      lcm_url = beft::lcmUrlForPort(port);
    } else {
      lcm_url = beft::defaultLcmUrl();
    }
  }
  options.lcm_url = lcm_url;

  std::map<std::string, std::string> overrides;
  for (const auto& set : sets) {
    const auto eq = set.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::fprintf(stderr, "[launch] error: --set '%s' is not NAME=VALUE\n", set.c_str());
      return 2;
    }
    overrides[set.substr(0, eq)] = set.substr(eq + 1);
  }
  overrides["lcm_url"] = lcm_url;
  try {
    const auto spec = beft::launch::loadLaunchFile(file, overrides);
    const auto outcome = beft::launch::supervise(spec, options);
    std::printf("[launch] %s\n", outcome.message.c_str());
    if (outcome.interrupted) return 130;
    if (outcome.arbiter_ran) return outcome.arbiter_exit_code == 0 ? 0 : 1;
    return 0;
  } catch (const beft::launch::LaunchError& e) {
    std::fprintf(stderr, "[launch] error: %s\n", e.what());
    return 2;
  }
}

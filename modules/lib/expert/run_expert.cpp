#include "lib/expert/run_expert.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <sstream>

#include "lib/common/heap_retention.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/expert/live_runner.hpp"
#include "lib/common/log.hpp"
#include "lib/expert/log_replay.hpp"
#include "lib/wire/message_decoder.hpp"
#include "lib/common/channels.hpp"

namespace beft::expert {

namespace {

std::string interfaceText(Expert& expert, const std::string& process_name) {
  std::ostringstream out;
  out << "process: " << process_name << "\n";
  out << "reads:\n";
  for (const auto& spec : expert.reads()) out << "  " << spec.channel << "  (" << spec.type << ")\n";
  out << "  " << channels::kFire << "  (" << channels::kFire.typeName() << ", tokens addressed to " << process_name
      << ")\n";
  out << "  " << channels::kRunStatus << "  (" << channels::kRunStatus.typeName() << ", stops at the end of the run)\n";
  out << "writes:\n";
  for (const auto& spec : expert.writes()) out << "  " << spec.channel << "  (" << spec.type << ")\n";
  out << "  " << channels::kDone << "  (" << channels::kDone.typeName() << ")\n";
  out << "  " << channels::kHeartbeat << "  (" << channels::kHeartbeat.typeName() << ")\n";
  const std::string parameters = expert.parameters().describe();
  if (!parameters.empty()) out << "parameters (--param NAME=VALUE):\n" << parameters;
  return out.str();
}

}  // namespace

int runExpertMain(int argc, char** argv, Expert& expert) {
  return runExpertMain(argc, argv, expert, nullptr);
}

int runExpertMain(int argc, char** argv, Expert& expert, const std::function<void(CLI::App&)>& add_options,
                  const std::function<std::optional<int>(const std::string& lcm_url)>& run_instead) {
  retainFreedHeapMemory();
  LiveOptions options;
  options.lcm_url = defaultLcmUrl();
  options.process_name = expert.name();
  std::vector<std::string> parameter_args;
  std::string replay_log;
  bool show_interface = false;

  CLI::App app(expert.description() +
               "\n\nRuns alone: start it with the same --lcm-url as the rest of the system; it "
               "catches up from the blackboard and fires when the arbiter sends FIRE tokens "
               "addressed to its --name. Offline: --replay LOG compares it with a recorded run.",
               expert.name());
  app.add_option("--lcm-url", options.lcm_url, "LCM URL (env BEFT_LCM_URL)")->capture_default_str();
  app.add_option("--name", options.process_name, "process name the arbiter fires")->capture_default_str();
  app.add_option("--param", parameter_args, "parameter NAME=VALUE (repeatable; see --interface)");
  app.add_option("--heartbeat-period", options.heartbeat_period_s, "seconds between heartbeats")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--ready-timeout", options.ready_timeout_s,
                 "longest wait for a firing's inputs before firing without them [s]; 0: never (lockstep runs stay "
                 "deterministic; a lost input is asked again of the blackboard after 1 s)")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  app.add_flag("--no-catch-up", [&](int64_t) { options.catch_up = false; },
               "do not ask the blackboard for the current state at start");
  app.add_option("--resume-log", options.resume_log,
                 "restarted after a crash: rebuild this expert's state from the run's LCM log (its inputs "
                 "and finished firings replayed, outputs dropped) before going live; the launcher passes it");
  app.add_option("--replay", replay_log, "run offline against this LCM log and compare outputs");
  app.add_flag("--interface", show_interface, "print the channels read and written, and the parameters");
  if (add_options) add_options(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  log::setProcessName(options.process_name);

  if (show_interface) {
    std::fputs(interfaceText(expert, options.process_name).c_str(), stdout);
    return 0;
  }

  Parameters parameters;
  for (const auto& arg : parameter_args) {
    const auto eq = arg.find('=');
    if (eq == std::string::npos || eq == 0) {
      log::error("--param '", arg, "' is not NAME=VALUE");
      return 2;
    }
    parameters[arg.substr(0, eq)] = arg.substr(eq + 1);
  }
  try {
    expert.startUp(parameters);
  } catch (const std::exception& e) {
    log::error("start-up failed: ", e.what());
    return 2;
  }

  if (!replay_log.empty()) {
    try {
      const ReplayResult result = replayLog(expert, options.process_name, replay_log);
      printReplayResult(result, options.process_name,
                        [](const std::string& channel, const std::vector<uint8_t>& bytes) {
                          return blackboard::describeMessage(channel, bytes.data(),
                                                             static_cast<int>(bytes.size()), 80);
                        });
      return result.exactMatch() ? 0 : result.logLacksInputs() ? 4 : 3;
    } catch (const std::exception& e) {
      log::error(e.what());
      return 1;
    }
  }
  if (run_instead)
    if (const std::optional<int> code = run_instead(options.lcm_url)) return *code;
  return runLive(expert, options);
}

}  // namespace beft::expert

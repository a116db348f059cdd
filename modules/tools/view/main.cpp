// beft-view: a run's log in the viewer (./beft view RUN.lcmlog | logs/<run>/):
// starts beft-bridge on it, prints the URL once it listens, and stops it on
// Ctrl-C.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lib/common/command_line.hpp"
#include "lib/common/own_bin_dir.hpp"
#include "lib/launch/tcp_port.hpp"
#include "tools/view/run_net.hpp"

namespace {

struct Options {
  std::string log;  // a run's log, or its folder
  int port = 8765;
  double speed = 1.0;
  bool paused = false;
  std::string net;  // the run's Petri net (default: the one its processes.log names)
  std::vector<std::string> bridge_args;  // after --
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Shows a run's log in the viewer: starts beft-bridge on it (the web page and the Foxglove WebSocket on one "
      "port of 127.0.0.1) and prints the URL; play, pause, step a tick and seek in the page (or in Foxglove: "
      "ws://127.0.0.1:PORT). Given a run's folder, plays its run.lcmlog and shows its processes.log. Ctrl-C stops.",
      "beft-view");
  app.add_option("log", o.log, "RUN.lcmlog, or a run's folder (logs/<run>/)")->required();
  app.add_option("--port", o.port, "TCP port (0: a free one)")->capture_default_str()->check(CLI::Range(0, 65535));
  app.add_option("--net", o.net,
                 "the run's Petri net (PNML), drawn in the page with its marking (default: given a run's folder, the "
                 "net its processes.log names, if that file is there)")
      ->check(CLI::ExistingFile);
  app.add_option("--speed", o.speed, "log seconds per second")->capture_default_str()->check(CLI::Range(0.01, 1000.0));
  app.add_flag("--paused", o.paused, "start paused");
  app.add_option("bridge_args", o.bridge_args, "after --: more options for beft-bridge (--bind, --token, --web-dir)");
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

// beft-bridge's command line for the log or folder given.
std::vector<std::string> bridgeCommand(const Options& o) {
  std::vector<std::string> command = {beft::ownBinDir() + "/beft-bridge", "--port", std::to_string(o.port),
                                      "--speed", std::to_string(o.speed)};
  if (std::filesystem::is_directory(o.log)) {
    command.insert(command.end(), {"--log", o.log + "/run.lcmlog", "--log-file", o.log + "/processes.log"});
    const std::string net = o.net.empty() ? beft::view::netOfRun(o.log + "/processes.log") : o.net;
    if (!net.empty()) command.insert(command.end(), {"--net", net});
  } else {
    if (!o.net.empty()) command.insert(command.end(), {"--net", o.net});
    command.insert(command.end(), {"--log", o.log});
  }
  if (o.paused) command.push_back("--paused");
  command.insert(command.end(), o.bridge_args.begin(), o.bridge_args.end());
  return command;
}

pid_t g_child = -1;
void forward(int signal) {
  if (g_child > 0) kill(g_child, signal);
}

pid_t start(const std::vector<std::string>& command) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv;
    for (const auto& arg : command) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    std::fprintf(stderr, "beft-view: cannot execute %s\n", argv[0]);
    _exit(127);
  }
  return pid;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  if (o.port == 0) o.port = beft::launch::findFreeTcpPort();
  if (o.port <= 0 || !beft::launch::tcpPortFree(o.port)) {
    std::fprintf(stderr, "beft-view: error: TCP port %d is taken: give --port N, or 0 for a free one\n", o.port);
    return 1;
  }
  g_child = start(bridgeCommand(o));
  if (g_child < 0) return 1;
  signal(SIGINT, forward);
  signal(SIGTERM, forward);
  if (beft::launch::waitForTcpListener("127.0.0.1", o.port, 60)) {
    std::printf("view: http://127.0.0.1:%d/\n", o.port);
    std::fflush(stdout);
  }
  int status = 0;
  while (waitpid(g_child, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 0;
}

// beft-record: records a run's LCM traffic into an LCM log (lcm-logplayer
// plays it). ./beft run and ./beft launch --record start it.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lcm_url.hpp"
#include "log.hpp"
#include "recorder.hpp"

namespace {
volatile std::sig_atomic_t g_stop = 0;
void onSignal(int) { g_stop = 1; }
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "beft-record: writes every message heard on the LCM URL into FILE, an LCM log file "
      "(lcm-logplayer plays it). On SIGINT or SIGTERM it records what is still arriving, "
      "then closes the file."};
  std::string lcm_url = beft::defaultLcmUrl();
  beft::record::RecordOptions options;
  bool quiet = false;
  app.add_option("file", options.path, "the log file to write")->required();
  app.add_option("--lcm-url", lcm_url, "LCM URL (env BEFT_LCM_URL)")->capture_default_str();
  app.add_option("--exclude", options.exclude_regex, "channels not recorded (POSIX extended regex, whole name)");
  app.add_flag("-f,--force", options.overwrite, "replace FILE if it exists");
  app.add_flag("-q,--quiet", quiet, "no summary at the end");
  CLI11_PARSE(app, argc, argv);
  beft::log::setProcessName("record");

  lcm::LCM lcm(lcm_url);
  if (!lcm.good()) {
    beft::log::error("cannot open LCM at ", lcm_url);
    return 1;
  }
  try {
    beft::record::Recorder recorder(lcm, options);
    beft::log::info("recording ", lcm_url, " into ", options.path);
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    // Flushed every second: at most that much is lost if the machine dies.
    auto next_flush = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    while (!g_stop) {
      if (!recorder.handle(100) && !g_stop) {
        beft::log::error("LCM receive failed; stopping");
        return 1;
      }
      if (std::chrono::steady_clock::now() >= next_flush) {
        recorder.flush();
        next_flush = std::chrono::steady_clock::now() + std::chrono::seconds(1);
      }
    }
    recorder.drain(100, 3000);
    recorder.flush();
    if (!quiet)
      beft::log::info("recorded ", recorder.events(), " messages (", recorder.bytes() / 1024, " KiB) to ",
                      options.path);
  } catch (const std::exception& e) {
    beft::log::error(e.what());
    return 1;
  }
  return 0;
}

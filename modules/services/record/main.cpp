// beft-record: records a run's LCM traffic into an LCM log (lcm-logplayer
// plays it). ./beft run and ./beft launch --record start it.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "heap_retention.hpp"
#include "lcm_url.hpp"
#include "log.hpp"
#include "recorder.hpp"

namespace {
volatile std::sig_atomic_t g_stop = 0;
void onSignal(int) { g_stop = 1; }
}  // namespace

int main(int argc, char** argv) {
  beft::retainFreedHeapMemory();
  CLI::App app{
      "beft-record: writes every message heard on the LCM URL into FILE, an LCM log file "
      "(lcm-logplayer plays it). On SIGINT or SIGTERM it records what is still arriving, "
      "then closes the file."};
  std::string lcm_url = beft::defaultLcmUrl();
  beft::record::RecordOptions options;
  bool quiet = false;
  int batch_ms = 5;
  app.add_option("file", options.path, "the log file to write")->required();
  app.add_option("--lcm-url", lcm_url, "LCM URL (env BEFT_LCM_URL)")->capture_default_str();
  app.add_option("--exclude", options.exclude_regex, "channels not recorded (POSIX extended regex, whole name)");
  app.add_flag("-f,--force", options.overwrite, "replace FILE if it exists");
  app.add_flag("-q,--quiet", quiet, "no summary at the end");
  app.add_option("--batch-ms", batch_ms,
                 "milliseconds to let messages gather between reads (one wake-up for many messages; the kernel "
                 "queues them meanwhile, with their receive times); 0 reads each as it comes")
      ->capture_default_str()
      ->check(CLI::Range(0, 50));
  CLI11_PARSE(app, argc, argv);
  beft::log::setProcessName("record");

  lcm::LCM lcm(lcm_url);
  if (!lcm.good()) {
    beft::log::error("cannot open LCM at ", lcm_url);
    return 1;
  }
  try {
    beft::record::Recorder recorder(lcm, lcm_url, options);
    beft::log::info("receiving: ", recorder.description());
    if (batch_ms > 0 && !beft::transport::roomToGather(recorder.receiveBufferBytes())) batch_ms = 0;
    beft::log::info("recording ", lcm_url, " into ", options.path);
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    // Flushed every second: at most that much is lost if the machine dies.
    auto next_flush = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    while (!g_stop) {
      const int handled = recorder.handle(100);
      if (handled < 0 && !g_stop) {
        beft::log::error("LCM receive failed; stopping");
        return 1;
      }
      // Let the next messages gather, unless this read was a large one
      // (a burst: keep up with it).
      if (handled > 0 && handled < 256 && batch_ms > 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(batch_ms));
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
    if (recorder.kernelDropped() > 0)
      beft::log::error(recorder.kernelDropped(), " datagram(s) lost before they were recorded: the receive "
                       "buffer was full (raise recv_buf_size in the LCM URL, or net.core.rmem_max)");
  } catch (const std::exception& e) {
    beft::log::error(e.what());
    return 1;
  }
  return 0;
}

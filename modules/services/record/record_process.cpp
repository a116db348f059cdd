#include "services/record/record_process.hpp"

#include <chrono>
#include <stdexcept>
#include <thread>

#include <CLI/CLI.hpp>

#include "lib/common/log.hpp"
#include "lib/transport/transport.hpp"

namespace beft::record {

std::string RecordProcess::description() const {
  return "beft-record: writes every message heard on the LCM URL into FILE, an LCM log file "
         "(lcm-logplayer plays it). On SIGINT or SIGTERM it records what is still arriving, "
         "then closes the file.";
}

void RecordProcess::addOptions(CLI::App& app) {
  app.add_option("file", options_.path, "the log file to write (required)");
  app.add_option("--exclude", options_.exclude_regex, "channels not recorded (POSIX extended regex, whole name)");
  app.add_option("--camera", camera_,
                 "camera frames recorded: all, none, or every:N (those of the ticks that are multiples of N); "
                 "the live processes get every frame")
      ->capture_default_str();
  app.add_flag("-f,--force", options_.overwrite, "replace FILE if it exists");
  app.add_flag("-q,--quiet", quiet_, "no summary at the end");
  app.add_option("--batch-ms", batch_ms_,
                 "milliseconds to let messages gather between reads (one wake-up for many messages; the kernel "
                 "queues them meanwhile, with their receive times); 0 reads each as it comes")
      ->capture_default_str()
      ->check(CLI::Range(0, 50));
}

void RecordProcess::recordUntilStopped(Recorder& recorder, const service::StopSignals& stop) {
  // Flushed every 100 ms: a restarted process resumes from the log (it
  // waits until the log holds what was published before it started), and
  // at most that much is lost if the machine dies.
  auto next_flush = std::chrono::steady_clock::now() + std::chrono::milliseconds(100);
  auto next_status = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  while (!stop.any()) {
    const int handled = recorder.handle(100);
    if (handled < 0 && !stop.any()) throw std::runtime_error("LCM receive failed; stopping");
    // Let the next messages gather, unless this read was a large one (a burst: keep up with it).
    if (handled > 0 && handled < 256 && batch_ms_ > 0) std::this_thread::sleep_for(std::chrono::milliseconds(batch_ms_));
    if (std::chrono::steady_clock::now() >= next_status) {
      recorder.writeStatus(false);
      next_status = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    }
    if (std::chrono::steady_clock::now() >= next_flush) {
      recorder.flush();
      next_flush = std::chrono::steady_clock::now() + std::chrono::milliseconds(100);
    }
  }
}

void RecordProcess::reportEnd(const Recorder& recorder) const {
  if (!quiet_)
    log::info("recorded ", recorder.events(), " messages (", recorder.bytes() / 1024, " KiB) to ", options_.path,
              recorder.cameraFramesLeftOut() > 0
                  ? "; " + std::to_string(recorder.cameraFramesLeftOut()) + " camera frames left out (--camera " +
                        options_.camera.text() + ")"
                  : std::string());
  const transport::RepairStats repairs = recorder.repairs();
  if (repairs.gaps > 0)
    log::info("loss repair: ", repairs.gaps, " message(s) missed at first, ", repairs.repaired, " repaired, ",
              repairs.lost + repairs.outstanding, " lost", recorder.kernelDropped() > 0
                  ? " (" + std::to_string(recorder.kernelDropped()) + " datagram(s) dropped by the kernel: the receive "
                    "buffer was full; raise recv_buf_size in the LCM URL, or net.core.rmem_max)"
                  : std::string());
  if (repairs.lost + repairs.outstanding > 0 || repairs.joined_late > 0)
    log::error("the log is not complete: ", repairs.lost + repairs.outstanding, " message(s) lost, ",
               repairs.joined_late, " stream(s) first heard late");
  for (const std::string& lost : repairs.lost_named) log::error("lost: ", lost);
}

void RecordProcess::onStartUp() {
  if (options_.path.empty()) throw std::invalid_argument("FILE is required: the log file to write");
  options_.camera = CameraSampling::parse(camera_);  // std::invalid_argument with the reason
}

int RecordProcess::serve(service::Context& context) {
  try {
    Recorder recorder(context.lcm, context.lcm_url, options_, recorded_.taken());
    log::info("receiving: ", recorder.description());
    if (batch_ms_ > 0 && !transport::roomToGather(recorder.receiveBufferBytes())) batch_ms_ = 0;
    log::info("recording ", context.lcm_url, " into ", options_.path,
              options_.camera.keepsAll() ? "" : " (camera frames: " + options_.camera.text() + ")");
    recordUntilStopped(recorder, context.stop);
    recorder.drain(100, 2000);  // within the launcher's 3 s grace to stop
    recorder.writeStatus(true);
    recorder.flush();
    reportEnd(recorder);
  } catch (const std::exception& e) {
    log::error(e.what());
    return 1;
  }
  return 0;
}

}  // namespace beft::record

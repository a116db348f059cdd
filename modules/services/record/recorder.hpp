// Writes what one LCM instance hears into an LCM log file (lcm-logger's
// format: lcm-logplayer plays it), in arrival order, with the receive time as
// the event timestamp: in a launched run, its own run's messages and the
// URL-wide beacons; another run's are counted (RECORD_STATUS), not written.
//
// Written for lockstep runs, which hand a burst of large messages to every
// process each tick: lcm-logger 1.3 keeps LCM's default 30 queued messages per
// subscription and drops the rest when it falls behind, passes each message
// through a writer thread (one more wake-up per message), and discards what
// is still queued when it is stopped. The recorder reads with the direct
// receiver (message_source.hpp: every datagram queued, one system call, the
// kernel's receive time as the timestamp), writes in the order messages
// entered the host (timestamp_order.hpp) into a buffered file, and on stop
// takes everything still arriving before it closes the file.
#pragma once

#include <cstdint>
#include <memory>

#include <regex>
#include <string>

#include "lib/launch/camera_sampling.hpp"
#include "services/record/timestamp_order.hpp"
#include "lib/transport/transport.hpp"

namespace lcm {
class LCM;
class LogFile;
}  // namespace lcm

namespace beft::record {

struct RecordOptions {
  std::string path;           // the log file to write
  bool overwrite = false;     // replace an existing file
  std::string exclude_regex;  // channels not recorded (empty: record all)
  CameraSampling camera;      // camera frames recorded (default: all)
  int queue_capacity = 100000;  // LCM's queue, when LCM's own receive thread is used
};

class Recorder {
 public:
  // Starts receiving what `taken` selects (RecordedPorts: every channel of
  // every run) on `url` (which `lcm` was opened with), then
  // creates the file (so once the file exists, everything sent is
  // recorded); throws std::runtime_error with the reason if it cannot.
  Recorder(lcm::LCM& lcm, const std::string& url, RecordOptions options, const transport::Selection& taken);
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  // Waits up to `timeout_ms` for messages and takes every one there; writes
  // those older than a millisecond, oldest first. Returns how many were
  // taken, -1 if receiving failed.
  int handle(int timeout_ms);
  // Keeps writing until nothing arrived for `quiet_ms` and nothing is still
  // being repaired (or `longest_ms` passed), then writes what it still holds.
  void drain(int quiet_ms, int longest_ms);
  void flush();

  int64_t events() const { return events_; }
  int64_t cameraFramesLeftOut() const { return camera_frames_left_out_; }
  int64_t bytes() const { return bytes_; }
  uint64_t kernelDropped() const { return source_->kernelDropped(); }
  // What loss repair did for the log: gaps found, repaired, given up.
  transport::RepairStats repairs() const { return source_->repairStats(); }
  // Writes the log's own account of its completeness (RECORD_STATUS,
  // record_status_t) into the log: every second while recording, and once
  // more, `final`, after the run. Complete: nothing known to be lost, nothing
  // still missing, no stream first heard after its early messages.
  void writeStatus(bool final);
  std::string description() const { return source_->description(); }
  // What the kernel granted the direct receiver's socket [bytes], -1 without one.
  int receiveBufferBytes() const { return source_->receiveBufferBytes(); }

 private:
  void write(const TimedEvent& event);
  void writeHeld();

  RecordOptions options_;
  std::unique_ptr<lcm::LogFile> log_;
  std::unique_ptr<transport::Receiver> source_;
  transport::Handler take_;
  TimestampOrder order_;
  std::regex exclude_;
  bool has_exclude_ = false;
  int64_t events_ = 0, bytes_ = 0;
  int64_t other_run_messages_ = 0;  // another run's, left out
  int64_t camera_frames_left_out_ = 0;
};

}  // namespace beft::record

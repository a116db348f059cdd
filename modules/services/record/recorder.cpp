#include "services/record/recorder.hpp"

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

#include <beft/record_status_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/common/log.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::record {

Recorder::Recorder(lcm::LCM& lcm, const std::string& url, RecordOptions options, const transport::Selection& taken)
    : options_(std::move(options)) {
  std::error_code error;
  if (!options_.overwrite && std::filesystem::exists(options_.path, error))
    throw std::runtime_error(options_.path + ": exists (--force replaces it)");
  if (!options_.exclude_regex.empty()) {
    try {
      exclude_ = std::regex(options_.exclude_regex, std::regex::extended);
      has_exclude_ = true;
    } catch (const std::regex_error& e) {
      throw std::runtime_error("--exclude '" + options_.exclude_regex + "': not a regular expression (" + e.what() + ")");
    }
  }
  // Listening before the file appears: whoever waits for the file to start
  // publishing (the launcher) loses nothing.
  source_ = transport::openReceiver(lcm, url, taken, 64, options_.queue_capacity);
  // A launched run's recorder keeps its own run (and the URL-wide beacons)
  // and counts the rest: a replayed log played at full speed on the URL
  // neither fills the disk nor holds the recorder back.
  const int64_t own_run = wire::runId();
  take_ = [this, own_run](const transport::Message& message) {
    if (own_run != 0 && wire::splitRunChannel(message.channel).run_id != own_run &&
        !wire::isUrlWideChannel(message.channel)) {
      ++other_run_messages_;
      return;
    }
    if (has_exclude_ && std::regex_match(message.channel.begin(), message.channel.end(), exclude_)) return;
    if (!options_.camera.keeps(message.channel, message.data, message.size)) {
      ++camera_frames_left_out_;
      return;
    }
    order_.add({std::string(message.channel), std::vector<uint8_t>(message.data, message.data + message.size),
                message.recv_utime});
  };
  log_ = std::make_unique<lcm::LogFile>(options_.path, "w");
  if (!log_->good()) throw std::runtime_error(options_.path + ": cannot be written");
}

Recorder::~Recorder() {
  writeHeld();
  flush();
}

void Recorder::write(const TimedEvent& event) {
  try {
    lcm::LogEvent entry;
    entry.eventnum = 0;  // the log file numbers events itself
    entry.timestamp = event.utime;
    entry.channel = event.channel;
    entry.datalen = static_cast<int32_t>(event.data.size());
    entry.data = const_cast<uint8_t*>(event.data.data());
    if (log_->writeEvent(&entry) != 0) throw std::runtime_error("write failed (disk full?)");
    ++events_;
    bytes_ += static_cast<int64_t>(event.data.size());
  } catch (const std::exception& e) {
    log::error("message on ", event.channel, " not recorded: ", e.what());
  }
}

int Recorder::handle(int timeout_ms) {
  const int taken = source_->receive(timeout_ms, take_);
  const int64_t now_us = std::chrono::duration_cast<std::chrono::microseconds>(
                             std::chrono::system_clock::now().time_since_epoch())
                             .count();
  order_.release(now_us, [this](const TimedEvent& event) { write(event); });
  return taken;
}

void Recorder::writeHeld() {
  order_.releaseAll([this](const TimedEvent& event) { write(event); });
}

void Recorder::drain(int quiet_ms, int longest_ms) {
  using Clock = std::chrono::steady_clock;
  const auto give_up = Clock::now() + std::chrono::milliseconds(longest_ms);
  while (Clock::now() < give_up) {
    const int taken = handle(quiet_ms);
    if (taken < 0) break;
    const transport::RepairStats repairs = source_->repairStats();
    if (taken == 0 && repairs.outstanding == 0 && repairs.waiting == 0) break;  // quiet, and nothing missing
  }
  writeHeld();
}

void Recorder::writeStatus(bool final) {
  const transport::RepairStats repairs = source_->repairStats();
  const int64_t now_us = std::chrono::duration_cast<std::chrono::microseconds>(
                             std::chrono::system_clock::now().time_since_epoch())
                             .count();
  beft::record_status_t status;
  status.utime = now_us;
  status.messages = events_;
  status.repaired = static_cast<int64_t>(repairs.repaired);
  // What is still missing at the end is lost to the log.
  status.lost = static_cast<int64_t>(repairs.lost + (final ? repairs.outstanding : 0));
  status.joined_late = static_cast<int64_t>(repairs.joined_late);
  status.kernel_dropped = static_cast<int64_t>(source_->kernelDropped());
  status.other_run_messages = other_run_messages_;
  status.complete = status.lost == 0 && repairs.outstanding == 0 && repairs.waiting == 0 && status.joined_late == 0;
  status.final = final;
  std::vector<uint8_t> bytes(static_cast<std::size_t>(status.getEncodedSize()));
  status.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  writeHeld();
  // Not one of the messages heard: events() and bytes() leave it out.
  const int64_t events = events_, written_bytes = bytes_;
  write({wire::runChannel(channels::kRecordStatus.name), std::move(bytes), now_us});
  events_ = events;
  bytes_ = written_bytes;
}

void Recorder::flush() {
  if (log_) std::fflush(log_->getFilePtr());
}

}  // namespace beft::record

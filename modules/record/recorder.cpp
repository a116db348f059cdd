#include "recorder.hpp"

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

#include "log.hpp"

namespace beft::record {

Recorder::Recorder(lcm::LCM& lcm, const std::string& url, RecordOptions options) : options_(std::move(options)) {
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
  // publishing (the launcher) loses nothing. Every channel: an empty list of
  // channels to drop.
  udpm_filter::Spec everything;
  everything.mode = udpm_filter::Spec::Mode::RejectListed;
  source_ = openMessageSource(lcm, url, everything, 64, options_.queue_capacity);
  writer_ = [this](const lcm_wire::Message& message) {
    try {
      write(message);
    } catch (const std::exception& e) {
      log::error("message on ", message.channel, " not recorded: ", e.what());
    }
  };
  log_ = std::make_unique<lcm::LogFile>(options_.path, "w");
  if (!log_->good()) throw std::runtime_error(options_.path + ": cannot be written");
}

Recorder::~Recorder() { flush(); }

void Recorder::write(const lcm_wire::Message& message) {
  const std::string channel(message.channel);
  if (has_exclude_ && std::regex_match(channel, exclude_)) return;
  lcm::LogEvent event;
  event.eventnum = 0;  // the log file numbers events itself
  event.timestamp = message.recv_utime;
  event.channel = channel;
  event.datalen = static_cast<int32_t>(message.size);
  event.data = const_cast<uint8_t*>(message.data);
  if (log_->writeEvent(&event) != 0) throw std::runtime_error("write failed (disk full?)");
  ++events_;
  bytes_ += static_cast<int64_t>(message.size);
}

int Recorder::handle(int timeout_ms) { return source_->receive(timeout_ms, writer_); }

void Recorder::drain(int quiet_ms, int longest_ms) {
  using Clock = std::chrono::steady_clock;
  const auto give_up = Clock::now() + std::chrono::milliseconds(longest_ms);
  while (Clock::now() < give_up) {
    if (handle(quiet_ms) <= 0) break;  // quiet for quiet_ms, or an error
  }
}

void Recorder::flush() {
  if (log_) std::fflush(log_->getFilePtr());
}

}  // namespace beft::record

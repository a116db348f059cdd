#include "recorder.hpp"

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

#include "log.hpp"

namespace beft::record {

Recorder::Recorder(lcm::LCM& lcm, RecordOptions options) : lcm_(lcm), options_(std::move(options)) {
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
  subscription_ = lcm_.subscribeFunction(".*", &Recorder::onMessageOf, this);
  subscription_->setQueueCapacity(options_.queue_capacity);
  lcm_get_fileno(lcm_.getUnderlyingLCM());  // LCM opens its receive socket here at the latest
  log_ = std::make_unique<lcm::LogFile>(options_.path, "w");
  if (!log_->good()) {
    lcm_.unsubscribe(subscription_);
    subscription_ = nullptr;
    throw std::runtime_error(options_.path + ": cannot be written");
  }
}

Recorder::~Recorder() {
  if (subscription_) lcm_.unsubscribe(subscription_);
  flush();
}

void Recorder::onMessageOf(const lcm::ReceiveBuffer* buffer, const std::string& channel, Recorder* self) {
  try {
    self->write(buffer, channel);
  } catch (const std::exception& e) {
    log::error("message on ", channel, " not recorded: ", e.what());
  }
}

void Recorder::write(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  if (has_exclude_ && std::regex_match(channel, exclude_)) return;
  lcm::LogEvent event;
  event.eventnum = 0;  // the log file numbers events itself
  event.timestamp = buffer->recv_utime;
  event.channel = channel;
  event.datalen = static_cast<int32_t>(buffer->data_size);
  event.data = buffer->data;
  if (log_->writeEvent(&event) != 0) throw std::runtime_error("write failed (disk full?)");
  ++events_;
  bytes_ += buffer->data_size;
}

bool Recorder::handle(int timeout_ms) { return lcm_.handleTimeout(timeout_ms) >= 0; }

void Recorder::drain(int quiet_ms, int longest_ms) {
  using Clock = std::chrono::steady_clock;
  const auto give_up = Clock::now() + std::chrono::milliseconds(longest_ms);
  while (Clock::now() < give_up) {
    const int handled = lcm_.handleTimeout(quiet_ms);
    if (handled <= 0) break;  // quiet for quiet_ms, or an error
  }
}

void Recorder::flush() {
  if (log_) std::fflush(log_->getFilePtr());
}

}  // namespace beft::record

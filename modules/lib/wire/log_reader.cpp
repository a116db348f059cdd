#include "lib/wire/log_reader.hpp"

#include <sys/stat.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "lib/wire/earlier_layouts.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::wire {

namespace {

constexpr uint32_t kSyncWord = 0xEDA1DA01;
constexpr std::size_t kHeaderBytes = 4 + 8 + 8 + 4 + 4;

uint64_t bigEndian(const uint8_t* bytes, int count) {
  uint64_t value = 0;
  for (int i = 0; i < count; ++i) value = (value << 8) | bytes[i];
  return value;
}

bool isChannelName(const std::string& channel) {
  for (unsigned char c : channel)
    if (!std::isgraph(c)) return false;
  return !channel.empty();
}

}  // namespace

std::string LogDamage::summary() const {
  if (!any()) return "";
  std::string text;
  if (damaged_stretches > 0)
    text = std::to_string(damaged_stretches) + " damaged stretch" + (damaged_stretches == 1 ? "" : "es") + " (" +
           std::to_string(bytes_skipped) + " bytes) skipped";
  if (cut_at_end) text += std::string(text.empty() ? "" : "; ") + "the last event is cut short";
  return text;
}

LogReader::LogReader(const std::string& path, uint64_t start_offset) : path_(path) {
  file_ = std::fopen(path.c_str(), "rb");
  if (file_ == nullptr) throw std::runtime_error("cannot open log " + path + ": " + std::strerror(errno));
  if (start_offset > 0 && fseeko(file_, static_cast<off_t>(start_offset), SEEK_SET) != 0) {
    std::fclose(file_);
    throw std::runtime_error("cannot seek in log " + path);
  }
  offset_ = end_of_last_event_ = start_offset;
  known_size_ = fileSize();
}

LogReader::~LogReader() {
  if (file_ != nullptr) std::fclose(file_);
}

uint64_t LogReader::fileSize() {
  struct stat status {};
  return fstat(fileno(file_), &status) == 0 ? static_cast<uint64_t>(status.st_size) : 0;
}

// Moves to just after the next sync word; false at the end of the file.
// Bytes passed on the way (and the record before, when it was damaged)
// count as one damaged stretch; bytes left at the end with no sync word
// are a cut record.
bool LogReader::findSync(bool after_damage) {
  uint32_t window = 0;
  uint64_t passed = 0;
  int c;
  while ((c = std::getc(file_)) != EOF) {
    ++offset_;
    window = (window << 8) | static_cast<uint32_t>(c);
    if (++passed >= 4 && window == kSyncWord) {
      if (passed > 4 || after_damage) {
        ++damage_.damaged_stretches;
        damage_.bytes_skipped += passed - 4;
      }
      return true;
    }
  }
  if (passed > 0 || after_damage) {
    damage_.cut_at_end = true;
    damage_.bytes_skipped += passed;
  }
  return false;
}

bool LogReader::readHeader(int64_t& event_number, int64_t& timestamp, int32_t& channel_length,
                           int32_t& data_length) {
  uint8_t header[kHeaderBytes - 4];
  if (std::fread(header, 1, sizeof header, file_) != sizeof header) return false;
  offset_ += sizeof header;
  event_number = static_cast<int64_t>(bigEndian(header, 8));
  timestamp = static_cast<int64_t>(bigEndian(header + 8, 8));
  channel_length = static_cast<int32_t>(bigEndian(header + 16, 4));
  data_length = static_cast<int32_t>(bigEndian(header + 20, 4));
  return true;
}

bool LogReader::next(LogEvent& event) {
  bool after_damage = false;
  while (true) {
    if (after_damage && fseeko(file_, static_cast<off_t>(offset_), SEEK_SET) != 0) return false;
    if (!findSync(after_damage)) return false;
    const uint64_t record_start = offset_ - 4;
    int64_t event_number, timestamp;
    int32_t channel_length, data_length;
    if (!readHeader(event_number, timestamp, channel_length, data_length)) {
      damage_.cut_at_end = true;
      return false;
    }
    const bool lengths_valid = channel_length > 0 && channel_length <= kMaxChannelLength && data_length >= 0 &&
                               data_length <= kMaxEventBytes;
    // A record longer than the file is a log cut mid-event, unless another
    // sync word follows (then its length was damaged): findSync tells.
    const uint64_t record_end =
        offset_ + static_cast<uint64_t>(channel_length) + static_cast<uint64_t>(data_length);
    if (lengths_valid && record_end > known_size_) known_size_ = fileSize();  // the log may still grow
    if (lengths_valid && record_end <= known_size_) {
      event.channel.resize(static_cast<std::size_t>(channel_length));
      event.data.resize(static_cast<std::size_t>(data_length));
      if (std::fread(event.channel.data(), 1, event.channel.size(), file_) == event.channel.size() &&
          std::fread(event.data.data(), 1, event.data.size(), file_) == event.data.size() &&
          isChannelName(event.channel)) {
        offset_ += static_cast<uint64_t>(channel_length) + static_cast<uint64_t>(data_length);
        end_of_last_event_ = offset_;
        event.event_number = event_number;
        event.timestamp = timestamp;
        upgradeEarlierLayout(event.data);  // a log older than a type's change reads as today's
        return true;
      }
    }
    offset_ = record_start + 1;
    after_damage = true;
  }
}

bool LogReader::nextOfRun(LogEvent& event, int64_t run_id) {
  while (next(event)) {
    const RunChannel split = splitRunChannel(event.channel);
    if (split.run_id != run_id && !isUrlWideChannel(event.channel)) {
      ++other_run_events_;
      continue;
    }
    if (split.run_id != 0) event.channel.resize(split.base.size());
    return true;
  }
  return false;
}

int64_t runOfLog(const std::string& path) {
  LogReader log(path);
  LogEvent event;
  int64_t first_run_seen = 0;
  while (log.next(event)) {
    const RunChannel split = splitRunChannel(event.channel);
    if (split.run_id == 0) continue;  // in a log with run ids, a plain channel is foreign
    if (split.base == "FIRE" || split.base == "MARKING") return split.run_id;
    if (first_run_seen == 0) first_run_seen = split.run_id;
  }
  return first_run_seen;
}

bool waitForLogPast(const std::string& path, int64_t since_us, double timeout_s) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  uint64_t offset = 0;
  while (true) {
    LogReader log(path, offset);
    LogEvent event;
    while (log.next(event))
      if (event.timestamp >= since_us) return true;
    offset = log.position();
    if (std::chrono::steady_clock::now() >= give_up) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace beft::wire

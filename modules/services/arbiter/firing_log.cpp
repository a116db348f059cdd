#include "services/arbiter/firing_log.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace beft::arbiter {

std::string formatFiringLine(const FiringRecord& record) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), "tick %5lld  firing %6lld  %-16s %-12s %9.3f ms",
                static_cast<long long>(record.tick), static_cast<long long>(record.firing_id),
                record.expert.c_str(), record.outcome.c_str(), record.duration_s * 1e3);
  std::string line = buffer;
  if (record.expert_duration_s >= 0.0) {
    std::snprintf(buffer, sizeof(buffer), "  (expert %.3f ms)", record.expert_duration_s * 1e3);
    line += buffer;
  }
  if (record.attempt > 1) line += "  attempt " + std::to_string(record.attempt);
  if (!record.action.empty()) line += "  -> " + record.action;
  if (!record.message.empty()) line += ": " + record.message;
  return line;
}

std::string firingCsvHeader() {
  return "tick,firing_id,expert,transition,attempt,start_s,duration_ms,expert_ms,outcome,action,message";
}

namespace {
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}
}  // namespace

std::string formatFiringCsvRow(const FiringRecord& record) {
  char numbers[128];
  std::snprintf(numbers, sizeof(numbers), "%.6f,%.3f,%.3f", record.start_s, record.duration_s * 1e3,
                record.expert_duration_s >= 0.0 ? record.expert_duration_s * 1e3 : -1.0);
  return std::to_string(record.tick) + "," + std::to_string(record.firing_id) + "," +
         csvField(record.expert) + "," + csvField(record.transition) + "," +
         std::to_string(record.attempt) + "," + numbers + "," + csvField(record.outcome) + "," +
         csvField(record.action) + "," + csvField(record.message);
}

FiringLog::FiringLog(std::FILE* lines, const std::string& csv_path, double flush_period_s)
    : lines_(lines),
      flush_period_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(flush_period_s))),
      last_flush_(std::chrono::steady_clock::now()) {
  if (csv_path.empty()) return;
  csv_.open(csv_path, std::ios::out | std::ios::trunc);
  if (!csv_) throw std::runtime_error(csv_path + ": cannot write the firing log: " + std::strerror(errno));
  csv_ << firingCsvHeader() << '\n';
}

void FiringLog::write(const FiringRecord& record) {
  if (lines_) {
    const std::string line = formatFiringLine(record);
    std::fprintf(lines_, "%s\n", line.c_str());
  }
  if (csv_.is_open()) csv_ << formatFiringCsvRow(record) << '\n';
  if (std::chrono::steady_clock::now() - last_flush_ >= flush_period_) flush();
}

void FiringLog::flush() {
  if (lines_) std::fflush(lines_);
  if (csv_.is_open()) csv_.flush();
  last_flush_ = std::chrono::steady_clock::now();
}

}  // namespace beft::arbiter

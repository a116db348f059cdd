#include "tools/spy/traffic_table.hpp"

#include <algorithm>
#include <cstdio>

namespace beft::spy {

std::string formatBytes(double bytes) {
  char text[32];
  if (bytes < 1e3)
    std::snprintf(text, sizeof text, "%.0f B", bytes);
  else if (bytes < 1e6)
    std::snprintf(text, sizeof text, "%.1f kB", bytes / 1e3);
  else
    std::snprintf(text, sizeof text, "%.1f MB", bytes / 1e6);
  return text;
}

TrafficTable::TrafficTable(double start_s, double window_s)
    : start_s_(start_s), window_s_(window_s > 0 ? window_s : 1.0) {}

void TrafficTable::forgetOld(Channel& channel, double now_s) const {
  while (!channel.recent.empty() && channel.recent.front().first <= now_s - window_s_) channel.recent.pop_front();
}

void TrafficTable::record(const std::string& channel_name, const std::string& type, std::size_t bytes, double now_s,
                          std::optional<int64_t> utime) {
  Channel& channel = channels_[channel_name];
  channel.type = type;
  ++channel.count;
  channel.last_bytes = bytes;
  channel.last_utime = utime;
  channel.last_time = now_s;
  channel.recent.emplace_back(now_s, bytes);
  forgetOld(channel, now_s);
  ++total_count_;
}

std::vector<TrafficRow> TrafficTable::rows(double now_s) const {
  const double span = std::min(window_s_, now_s - start_s_);
  std::vector<TrafficRow> result;
  for (const auto& [name, channel] : channels_) {
    TrafficRow row;
    row.channel = name;
    row.type = channel.type;
    row.count = channel.count;
    row.last_bytes = channel.last_bytes;
    row.last_utime = channel.last_utime;
    row.idle_s = now_s - channel.last_time;
    std::size_t in_window = 0;
    double bytes_in_window = 0;
    for (const auto& [time, bytes] : channel.recent) {
      if (time <= now_s - window_s_ || time > now_s) continue;
      ++in_window;
      bytes_in_window += static_cast<double>(bytes);
    }
    if (span > 0) {
      row.rate_hz = static_cast<double>(in_window) / span;
      row.bytes_per_second = bytes_in_window / span;
    }
    result.push_back(row);
  }
  return result;
}

std::string TrafficTable::format(double now_s) const {
  const auto table = rows(now_s);
  std::size_t channel_width = 7, type_width = 4;
  for (const auto& row : table) {
    channel_width = std::max(channel_width, row.channel.size());
    type_width = std::max(type_width, row.type.size());
  }
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line, "%-*s  %-*s  %8s  %8s  %9s  %10s  %12s  %7s\n", static_cast<int>(channel_width),
                "CHANNEL", static_cast<int>(type_width), "TYPE", "COUNT", "RATE Hz", "SIZE", "RATE", "UTIME s",
                "IDLE s");
  out += line;
  double total_rate = 0, total_bandwidth = 0;
  for (const auto& row : table) {
    char utime[32] = "-";
    if (row.last_utime) std::snprintf(utime, sizeof utime, "%.3f", static_cast<double>(*row.last_utime) / 1e6);
    std::snprintf(line, sizeof line, "%-*s  %-*s  %8llu  %8.1f  %9s  %8s/s  %12s  %7.1f\n",
                  static_cast<int>(channel_width), row.channel.c_str(), static_cast<int>(type_width), row.type.c_str(),
                  static_cast<unsigned long long>(row.count), row.rate_hz,
                  formatBytes(static_cast<double>(row.last_bytes)).c_str(), formatBytes(row.bytes_per_second).c_str(),
                  utime, row.idle_s);
    out += line;
    total_rate += row.rate_hz;
    total_bandwidth += row.bytes_per_second;
  }
  std::snprintf(line, sizeof line, "%zu channel(s), %llu message(s), %.1f Hz, %s/s in all\n", table.size(),
                static_cast<unsigned long long>(total_count_), total_rate, formatBytes(total_bandwidth).c_str());
  out += line;
  return out;
}

}  // namespace beft::spy

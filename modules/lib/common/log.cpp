#include "lib/common/log.hpp"

#include <cstdio>
#include <mutex>

namespace beft::log {
namespace {
std::mutex g_mutex;
std::string g_name = "beft";
Level g_level = Level::Info;
const char* levelName(Level level) {
  switch (level) {
    case Level::Debug: return "debug";
    case Level::Info: return "info";
    case Level::Warn: return "WARN";
    case Level::Error: return "ERROR";
  }
  return "?";
}
}  // namespace

void setProcessName(const std::string& name) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_name = name;
}

void setLevel(Level level) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_level = level;
}

void write(Level level, const std::string& message) {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (level < g_level) return;
  std::fflush(stdout);  // what a program printed before this line stays before it in a shared pipe
  std::fprintf(stderr, "[%s] %s: %s\n", g_name.c_str(), levelName(level), message.c_str());
  std::fflush(stderr);
}

}  // namespace beft::log

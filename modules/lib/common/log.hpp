// Readable process logs: "[name] LEVEL message" on stderr, one line each.
#pragma once

#include <sstream>
#include <string>

namespace beft::log {

enum class Level { Debug = 0, Info = 1, Warn = 2, Error = 3 };

void setProcessName(const std::string& name);
void setLevel(Level level);
void write(Level level, const std::string& message);

namespace detail {
inline void append(std::ostringstream&) {}
template <typename T, typename... Rest>
void append(std::ostringstream& out, const T& first, const Rest&... rest) {
  out << first;
  append(out, rest...);
}
template <typename... Args>
std::string join(const Args&... args) {
  std::ostringstream out;
  append(out, args...);
  return out.str();
}
}  // namespace detail

template <typename... Args> void debug(const Args&... a) { write(Level::Debug, detail::join(a...)); }
template <typename... Args> void info(const Args&... a) { write(Level::Info, detail::join(a...)); }
template <typename... Args> void warn(const Args&... a) { write(Level::Warn, detail::join(a...)); }
template <typename... Args> void error(const Args&... a) { write(Level::Error, detail::join(a...)); }

}  // namespace beft::log

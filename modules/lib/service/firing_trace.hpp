// The arbiter's trace of firings, one line each in the processes' log
// ("tick     3  firing    31  vision            ok       0.41 ms  (expert
// 0.30 ms)", services/arbiter/firing_log.hpp): what a reader of that log
// needs to tell such a line from the others. At full speed the trace is
// almost every line of a run's log (ten a tick), so a viewer shows it apart
// from the lines that say something (services/bridge: /log and /firings).
#pragma once

#include <cctype>
#include <string_view>

namespace beft::service {

// The words a firing line starts with: "tick", the tick, "firing", the firing id.
inline constexpr std::string_view kFiringTraceTick = "tick ";
inline constexpr std::string_view kFiringTraceFiring = "firing ";

namespace detail {
// Skips spaces, then one unsigned number; false when there is none.
inline bool skipNumber(std::string_view text, std::size_t& at) {
  while (at < text.size() && text[at] == ' ') ++at;
  const std::size_t start = at;
  while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]))) ++at;
  return at > start;
}
// The next word after spaces.
inline std::string_view nextWord(std::string_view text, std::size_t& at) {
  while (at < text.size() && text[at] == ' ') ++at;
  const std::size_t start = at;
  while (at < text.size() && text[at] != ' ') ++at;
  return text.substr(start, at - start);
}
}  // namespace detail

struct FiringTraceLine {
  bool is_firing = false;  // the line is one of the arbiter's firing lines
  bool routine = false;    // and says only that an expert's firing went well ("ok", nothing after the times)
};

// Reads the arbiter's text of a processes.log line (without "[arbiter] ").
inline FiringTraceLine readFiringTraceLine(std::string_view text) {
  FiringTraceLine line;
  if (text.substr(0, kFiringTraceTick.size()) != kFiringTraceTick) return line;
  std::size_t at = kFiringTraceTick.size();
  if (!detail::skipNumber(text, at)) return line;
  while (at < text.size() && text[at] == ' ') ++at;
  if (text.substr(at, kFiringTraceFiring.size()) != kFiringTraceFiring) return line;
  at += kFiringTraceFiring.size();
  if (!detail::skipNumber(text, at)) return line;
  line.is_firing = true;
  detail::nextWord(text, at);  // the expert
  const bool ok = detail::nextWord(text, at) == "ok";
  // After the times only a retry ("attempt 2"), an action ("-> ...") or a message (": ...") may follow.
  const std::string_view rest = text.substr(at);
  line.routine = ok && rest.find("attempt") == std::string_view::npos && rest.find("->") == std::string_view::npos &&
                 rest.find(": ") == std::string_view::npos;
  return line;
}

}  // namespace beft::service

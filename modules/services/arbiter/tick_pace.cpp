#include "services/arbiter/tick_pace.hpp"

#include <limits>
#include <stdexcept>

namespace beft::arbiter {

Pace parsePace(const std::string& text) {
  if (text == "fast") return Pace::kFast;
  if (text == "real-time") return Pace::kRealTime;
  throw std::invalid_argument("unknown pace '" + text + "' (fast or real-time)");
}

const char* paceName(Pace pace) { return pace == Pace::kRealTime ? "real-time" : "fast"; }

double TickPace::earliestStart(int64_t tick) const {
  if (pace_ == Pace::kFast) return -std::numeric_limits<double>::infinity();
  return origin_s_ + static_cast<double>(tick - origin_tick_) * dt_s_;
}

}  // namespace beft::arbiter

// The two clocks, in microseconds: the steady one for waits and back-offs,
// the wall clock for what travels (utime fields, when a stream began), which
// other hosts compare with theirs.
#pragma once

#include <chrono>
#include <cstdint>

namespace beft {

inline int64_t steadyMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

inline int64_t wallMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace beft

// The time stamp of an encoded beft message, read without decoding it (a
// camera frame or an obstacle map need not be): every per-tick type begins
// with `int64_t utime; int64_t tick;`, right after LCM's 8-byte fingerprint,
// big-endian.
#pragma once

#include <cstddef>
#include <cstdint>

namespace beft::wire {

// False (the value untouched) if the bytes are too short to hold it.
bool encodedUtime(const uint8_t* data, std::size_t size, int64_t& utime);
bool encodedTick(const uint8_t* data, std::size_t size, int64_t& tick);

}  // namespace beft::wire

// Messages of an earlier layout of a beft type, rewritten into today's as a
// log is read, so that logs recorded before a type changed stay readable
// (log_reader.cpp calls it on every event).
//
// Types change by adding new ones, never by editing old ones, with one
// exception so far: camera_frame_t gained `compression` (COMPRESSION_NONE =
// the pixels as before) when frames began to travel compressed. An earlier
// frame is the same bytes without that one, so it is rewritten losslessly.
#pragma once

#include <cstdint>
#include <vector>

namespace beft::wire {

// If data is an encoded message of an earlier layout (its fingerprint says
// so), rewrites it into today's layout and returns true; else leaves it.
// Nothing else is checked: the result is as untrusted as the input.
bool upgradeEarlierLayout(std::vector<uint8_t>& data);

}  // namespace beft::wire

// Messages of an earlier layout of a beft type, rewritten into today's as a
// log is read, so that logs recorded before a type changed stay readable
// (log_reader.cpp calls it on every event).
//
// Types change by adding new ones, never by editing old ones, with a few
// exceptions so far: camera_frame_t gained `compression` (COMPRESSION_NONE =
// the pixels as before) when frames began to travel compressed;
// run_beacon_t gained `description` and `started_utime` (0: not known) when
// the hosts of a distributed run began to agree on a fresh run id; fire_t and
// done_t gained what a firing comes after and what an expert had published
// (0 and nothing) when lost messages began to be repaired; hypothesis_t and
// acoustic_percept_t gained `located` (false) when the explorer began to
// tell a heard crossing from a point along a bearing, which changed the
// messages that hold them (hypotheses_t, hypothesis_changes_t,
// acoustic_percepts_t). An earlier message is the same bytes without those,
// so it is rewritten losslessly.
#pragma once

#include <cstdint>
#include <vector>

namespace beft::wire {

// If data is an encoded message of an earlier layout (its fingerprint says
// so), rewrites it into today's layout and returns true; else leaves it.
// Nothing else is checked: the result is as untrusted as the input.
bool upgradeEarlierLayout(std::vector<uint8_t>& data);

}  // namespace beft::wire

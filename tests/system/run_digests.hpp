// A compact fingerprint of a run's data messages, pinned in tests/system/data/
// so that a change meant to alter no message (a refactoring, a speed-up) is
// checked against the build before it without keeping its logs.
//
// Per channel: how many messages and a 64-bit FNV-1a hash over their bytes in
// order (data_digests.json), and per message a 32-bit hash
// (message_fingerprints.json) that only serves to name the first message that
// differs. What is hashed of a message: its bytes as encoded; a camera frame
// or an obstacle map once unpacked (its pixels or cells, whatever zstd made of
// them); with HYPOTHESIS_CHANGES (OBSTACLE_MAP_CHANGES), HYPOTHESES
// (OBSTACLE_MAP) stands for the whole list (map) of every tick, made from the
// keyframes and the changes.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/system/run_support.hpp"

namespace beft::system_test {

struct ChannelDigest {
  std::size_t count = 0;
  uint64_t hash = 1469598103934665603ull;  // FNV-1a offset basis
};

struct RunDigests {
  std::map<std::string, ChannelDigest> channels;
  std::map<std::string, std::vector<uint32_t>> fingerprints;  // per message, in the digest's order
};

RunDigests digestRun(const std::vector<LoggedMessage>& log);

// A run's entry of data_digests.json: {"CHANNEL": {"count": N, "fnv1a64": "hex"}}.
nlohmann::json digestsAsJson(const RunDigests& digests);
// A run's entry of message_fingerprints.json: {"CHANNEL": "8 hex digits per message"}.
nlohmann::json fingerprintsAsJson(const RunDigests& digests);

// "" when the run's digests are the pinned ones; else every channel that
// differs, and the earliest message that differs named (channel, index,
// tick) and decoded as the run has it.
std::string digestMismatch(const std::vector<LoggedMessage>& log, const RunDigests& digests,
                           const nlohmann::json& pinned, const nlohmann::json& pinned_fingerprints);

}  // namespace beft::system_test

// LCM's UDP multicast datagram format (LCM 1.x, "lcm2" packets), as LCM's
// udpm provider writes it:
//   short message:  "LC02" | sequence number | channel NUL | payload
//   fragment:       "LC03" | sequence number | message size | fragment offset |
//                   fragment number (16 bit) | fragment count (16 bit) |
//                   [channel NUL, in fragment 0 only] | payload part
// All integers big-endian. A message whose channel and payload exceed one
// datagram is sent as fragments that share the sequence number.
//
// Read by the direct receiver (udpm_receiver.hpp); LCM itself still does every
// publish, so nothing here writes packets but the tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lib/transport/transport.hpp"

namespace beft::lcm_wire {

constexpr uint32_t kMagicShort = 0x4c433032;     // "LC02"
constexpr uint32_t kMagicFragment = 0x4c433033;  // "LC03"
constexpr std::size_t kShortHeaderBytes = 8;
constexpr std::size_t kFragmentHeaderBytes = 20;
constexpr std::size_t kMaxChannelLength = 63;         // LCM_MAX_CHANNEL_NAME_LENGTH
constexpr uint32_t kMaxMessageBytes = 1u << 28;       // LCM_MAX_MESSAGE_SIZE
constexpr std::size_t kLargestDatagram = 65535;       // what LCM reads per packet

// One datagram, parsed. Views point into the datagram's bytes.
struct Packet {
  enum class Kind { Short, Fragment, Invalid };
  Kind kind = Kind::Invalid;
  std::string invalid_reason;     // for Invalid
  uint32_t sequence = 0;
  std::string_view channel;       // Short, and fragment 0
  const uint8_t* payload = nullptr;
  std::size_t payload_size = 0;
  // Fragment only:
  uint32_t message_size = 0;      // [bytes] of the whole payload
  uint32_t fragment_offset = 0;   // [bytes] where this part goes
  uint16_t fragment_index = 0;
  uint16_t fragment_count = 0;
};

Packet parsePacket(const uint8_t* bytes, std::size_t size);

// A complete message: the channel and its encoded bytes.
using Message = transport::Message;

// Puts fragmented messages back together, per sender and sequence number.
// Fragments may come in any order. A message whose fragments stop coming is
// dropped, oldest first, when more than `max_partial` messages or more than
// kMaxPartialBytes are open at once (LCM keeps 16 MB of them).
class FragmentAssembler {
 public:
  static constexpr std::size_t kMaxPartialBytes = std::size_t{64} << 20;
  explicit FragmentAssembler(std::size_t max_partial = 64) : max_partial_(max_partial) {}

  // Adds one fragment from `sender` (any id unique per sending socket). When
  // it completes its message, returns true and points `out` at it; the bytes
  // stay valid until the next call.
  bool add(uint64_t sender, const Packet& fragment, int64_t recv_utime, Message& out);

  std::size_t partialMessages() const { return partial_.size(); }
  uint64_t droppedIncomplete() const { return dropped_incomplete_; }
  uint64_t rejectedFragments() const { return rejected_fragments_; }

 private:
  struct Partial {
    std::string channel;
    std::vector<uint8_t> data;
    std::vector<bool> received;
    uint16_t remaining = 0;
    uint64_t age = 0;  // order opened, for eviction
  };
  using Key = std::pair<uint64_t, uint32_t>;  // sender, sequence number

  void dropPartial(std::map<Key, Partial>::iterator which);

  const std::size_t max_partial_;
  std::map<Key, Partial> partial_;
  std::size_t partial_bytes_ = 0;
  uint64_t opened_ = 0;
  uint64_t dropped_incomplete_ = 0;
  uint64_t rejected_fragments_ = 0;
  std::string done_channel_;
  std::vector<uint8_t> done_data_;
};

}  // namespace beft::lcm_wire

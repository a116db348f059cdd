// What a tag costs one message: made by its sender, checked by each receiver
// (libsodium's keyed BLAKE2b over channel, sender, number and payload).
#pragma once

#include <cstddef>

namespace beft::bench {

struct TagCost {
  std::size_t bytes = 0;      // payload size
  double make_us = 0;         // tagging it, per message [us]
  double check_us = 0;        // checking the tag, per message [us]
};

// Tags and checks `rounds` messages of `bytes` bytes; the mean cost of each.
TagCost measureTagCost(std::size_t bytes, int rounds);

}  // namespace beft::bench

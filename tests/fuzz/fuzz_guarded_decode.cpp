// The guarded decode of every beft type on any bytes: what passes decodes
// and encodes back to the same bytes; the readable decoder never crashes.
#include <cstdlib>
#include <vector>

#include "lib/wire/message_decoder.hpp"
#include "every_beft_type.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::vector<uint8_t> bytes(data, data + size);
  for (const auto& [type, round_trip] : everyBeftType()) {
    const GuardedRoundTrip result = round_trip(bytes);
    if (result.verdict.ok() && result.encoded_again != bytes) std::abort();
  }
  beft::blackboard::describeMessage("FUZZ", data, static_cast<int>(size), 20);
  return 0;
}

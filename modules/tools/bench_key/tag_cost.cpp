#include "tools/bench_key/tag_cost.hpp"

#include <chrono>
#include <vector>

#include "lib/transport/message_key.hpp"

namespace beft::bench {

namespace {

using Clock = std::chrono::steady_clock;

double microsecondsEach(Clock::time_point start, int rounds) {
  return std::chrono::duration<double, std::micro>(Clock::now() - start).count() / rounds;
}

}  // namespace

TagCost measureTagCost(std::size_t bytes, int rounds) {
  const transport::MessageKey key = transport::MessageKey::random();
  std::vector<uint8_t> payload(bytes);
  for (std::size_t i = 0; i < bytes; ++i) payload[i] = static_cast<uint8_t>(i * 31);
  const std::string channel = "CAMERA_COLOR@1f2e3d4c5b6a7988";
  TagCost cost;
  cost.bytes = bytes;
  wire::Envelope envelope;
  envelope.sender = 12345;
  envelope.tagged = true;
  auto start = Clock::now();
  for (int i = 0; i < rounds; ++i)
    envelope.tag = transport::tagOf(key, channel, envelope.sender, ++envelope.sequence, payload.data(), bytes);
  cost.make_us = microsecondsEach(start, rounds);
  int valid = 0;
  start = Clock::now();
  for (int i = 0; i < rounds; ++i) valid += transport::tagValid(key, channel, envelope, payload.data(), bytes);
  cost.check_us = microsecondsEach(start, rounds);
  if (valid != rounds) cost.check_us = -1;  // never: the last tag is checked again and again
  return cost;
}

}  // namespace beft::bench

// The report tests' logs, written message by message as a run's recorder
// would (lcm-logger's format).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

namespace beft::report_test {

template <typename Message>
void write(lcm::LogFile& log, const std::string& channel, const Message& message, int64_t timestamp) {
  std::vector<uint8_t> bytes(message.getEncodedSize());
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  lcm::LogEvent event;
  event.eventnum = 0;
  event.timestamp = timestamp;
  event.channel = channel;
  event.datalen = static_cast<int32_t>(bytes.size());
  event.data = bytes.data();
  ASSERT_EQ(log.writeEvent(&event), 0);
}

}  // namespace beft::report_test

// Refused messages: counted per channel, logged at most once a second per channel.
#include <gtest/gtest.h>

#include "lib/wire/reject_counter.hpp"

using beft::wire::Fault;
using beft::wire::RejectCounter;
using beft::wire::Verdict;

TEST(RejectCounter, CountsEveryRefusalButLogsAtMostOnceASecondPerChannel) {
  RejectCounter counter;
  const auto start = RejectCounter::Clock::now();
  const Verdict verdict{Fault::kTrailingBytes, "fire_t"};
  // 3000 a second for 2.5 s on two channels.
  for (int i = 0; i < 7500; ++i) {
    const auto now = start + std::chrono::microseconds(i * 333);
    counter.count("FIRE", verdict, now);
    counter.count("VISION", verdict, now);
  }
  EXPECT_EQ(counter.totals().at("FIRE"), 7500u);
  EXPECT_EQ(counter.totals().at("VISION"), 7500u);
  EXPECT_EQ(counter.total(), 15000u);
  // At 0 s, 1 s and 2 s, for each channel.
  EXPECT_EQ(counter.linesLogged(), 6u);
}

// beft-bench-view's readers: the page probe's lines and a log's tick times.
#include <gtest/gtest.h>

#include "tools/bench_view/page_probe.hpp"
#include "tools/bench_view/tick_times.hpp"

namespace {

using beft::bench::parseProbeOutput;
using beft::bench::TickTimes;

TEST(ProbeOutput, ReadsConnectionSamplesAndErrors) {
  const auto readings = parseProbeOutput(
      "browser: Chrome/1\n"
      "connected: 1700000000000 3\n"
      "sample: 1700000001000 12 16.5 60 40 450 86 true\n"
      "page error: TypeError: x\n"
      "sample: 1700000002000 22 17.5 120 80 450 87 true\n");
  EXPECT_TRUE(readings.unavailable.empty());
  EXPECT_EQ(readings.connected_ms, 1700000000000);
  ASSERT_EQ(readings.samples.size(), 2u);
  EXPECT_EQ(readings.samples[1].tick, 22);
  EXPECT_DOUBLE_EQ(readings.samples[1].frame_time_ms, 17.5);
  EXPECT_EQ(readings.samples[1].frames, 120);
  EXPECT_EQ(readings.samples[1].renders, 80);
  EXPECT_EQ(readings.samples[1].hypotheses, 87);
  EXPECT_EQ(readings.page_errors.size(), 1u);
}

TEST(ProbeOutput, SaysWhyThePageCouldNotBeOpened) {
  const auto readings = parseProbeOutput("unavailable: chromium is not installed\n");
  EXPECT_EQ(readings.unavailable, "chromium is not installed");
  EXPECT_EQ(readings.connected_ms, -1);
  EXPECT_TRUE(readings.samples.empty());
}

TEST(ProbeOutput, LeavesOutACutSample) {
  EXPECT_TRUE(parseProbeOutput("sample: 1700000001000 12 16.5\n").samples.empty());
}

TEST(TickTimes, MeasuresFromTheFirstTickFiredAfterATime) {
  TickTimes times;
  times.first_fire_us = {{0, 1'000'000}, {1, 1'010'000}, {2, 5'000'000}, {3, 5'010'000}};  // held after tick 1
  times.last_done_us = 5'020'000;
  EXPECT_EQ(times.firstTickFiredAfter(2'000'000), 2);
  EXPECT_EQ(times.firstTickFiredAfter(6'000'000), -1);
  EXPECT_NEAR(times.ticksPerSecondFrom(2), 2 / 0.02, 1e-6);  // the hold before tick 2 is left out
  EXPECT_NEAR(times.ticksPerSecondFrom(0), 4 / 4.02, 1e-6);
  EXPECT_EQ(times.ticksPerSecondFrom(7), 0);
}

TEST(TickTimes, TheTickUnderWayAtATime) {
  TickTimes times;
  times.first_fire_us = {{0, 1'000'000}, {1, 1'010'000}, {2, 5'000'000}};
  EXPECT_EQ(times.tickAt(999'999), -1);
  EXPECT_EQ(times.tickAt(1'010'000), 1);
  EXPECT_EQ(times.tickAt(4'999'999), 1);
  EXPECT_EQ(times.tickAt(9'000'000), 2);
}

TEST(TickTimes, AMissingLogHasNoTicks) {
  const auto times = beft::bench::readTickTimes("no such folder/run.lcmlog");
  EXPECT_TRUE(times.first_fire_us.empty());
  EXPECT_EQ(times.ticksPerSecondFrom(0), 0);
}

}  // namespace

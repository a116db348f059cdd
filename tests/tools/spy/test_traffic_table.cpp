// The spy's per-channel counts, rates and table.
#include <gtest/gtest.h>

#include <string>

#include "tools/spy/traffic_table.hpp"

using beft::spy::TrafficTable;

TEST(TrafficTable, CountsAndRatePerChannel) {
  TrafficTable table(0.0, 2.0);
  // 10 Hz on A for 3 s, 2 Hz on B.
  for (int i = 1; i <= 30; ++i) table.record("A", "beft.robot_state_t", 100, i * 0.1, i * 100000);
  for (int i = 1; i <= 6; ++i) table.record("B", "beft.hypotheses_t", 1000, i * 0.5, std::nullopt);
  const auto rows = table.rows(3.0);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].channel, "A");
  EXPECT_EQ(rows[0].type, "beft.robot_state_t");
  EXPECT_EQ(rows[0].count, 30u);
  // Messages at (1.0, 3.0]: 20 over 2 s.
  EXPECT_NEAR(rows[0].rate_hz, 10.0, 1e-9);
  EXPECT_NEAR(rows[0].bytes_per_second, 1000.0, 1e-9);
  EXPECT_EQ(*rows[0].last_utime, 3000000);
  EXPECT_EQ(rows[1].count, 6u);
  EXPECT_NEAR(rows[1].rate_hz, 2.0, 1e-9);
  EXPECT_FALSE(rows[1].last_utime.has_value());
  EXPECT_EQ(table.totalCount(), 36u);
}

TEST(TrafficTable, YoungSpyDividesByItsAge) {
  TrafficTable table(10.0, 5.0);
  table.record("A", "t", 1, 10.25, 0);
  table.record("A", "t", 1, 10.5, 0);
  EXPECT_NEAR(table.rows(11.0)[0].rate_hz, 2.0, 1e-9);  // 2 messages in the first second
}

TEST(TrafficTable, SilentChannelDropsToZeroButKeepsItsCount) {
  TrafficTable table(0.0, 1.0);
  table.record("A", "t", 10, 0.5, 0);
  const auto rows = table.rows(5.0);
  EXPECT_EQ(rows[0].count, 1u);
  EXPECT_EQ(rows[0].rate_hz, 0.0);
  EXPECT_NEAR(rows[0].idle_s, 4.5, 1e-9);
}

TEST(TrafficTable, FormatHasAHeaderALinePerChannelAndATotal) {
  TrafficTable table(0.0, 1.0);
  table.record("ROBOT_STATE", "beft.robot_state_t", 312, 0.5, 4200000);
  table.record("CAMERA_COLOR", "beft.camera_frame_t", 2400000, 0.6, 4200000);
  const std::string text = table.format(1.0);
  EXPECT_EQ(text.find("CHANNEL"), 0u);
  EXPECT_NE(text.find("ROBOT_STATE"), std::string::npos);
  EXPECT_NE(text.find("beft.camera_frame_t"), std::string::npos);
  EXPECT_NE(text.find("2.4 MB"), std::string::npos);
  EXPECT_NE(text.find("312 B"), std::string::npos);
  EXPECT_NE(text.find("4.200"), std::string::npos);
  EXPECT_NE(text.find("2 channel(s), 2 message(s)"), std::string::npos);
  // CAMERA_COLOR sorts first.
  EXPECT_LT(text.find("CAMERA_COLOR"), text.find("ROBOT_STATE"));
}

TEST(TrafficTable, FormatBytes) {
  EXPECT_EQ(beft::spy::formatBytes(999), "999 B");
  EXPECT_EQ(beft::spy::formatBytes(45100), "45.1 kB");
  EXPECT_EQ(beft::spy::formatBytes(2.3e6), "2.3 MB");
}

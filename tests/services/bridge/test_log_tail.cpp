// The processes' log followed as it grows, cut or replaced.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "services/bridge/log_tail.hpp"

using beft::bridge::LogTail;
using beft::bridge::splitProcessLine;

TEST(LogTail, FollowsWholeLinesAndStartsAgainWhenCut) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("beft_tail_" + std::to_string(getpid()) + ".log")).string();
  std::filesystem::remove(path);
  LogTail tail(path);
  EXPECT_TRUE(tail.newLines().empty());  // not there yet
  std::ofstream(path) << "[world] tick 1\n[vision] half";
  auto lines = tail.newLines();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "[world] tick 1");
  std::ofstream(path, std::ios::app) << " a line\n";
  lines = tail.newLines();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "[vision] half a line");
  std::ofstream(path, std::ios::trunc) << "new\n";
  lines = tail.newLines();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "new");
  std::filesystem::remove(path);
}

TEST(LogTail, StartsNearTheEndOfABigFile) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("beft_tail_big_" + std::to_string(getpid()) + ".log")).string();
  {
    std::ofstream out(path);
    for (int i = 0; i < 10000; ++i) out << "[world] line " << i << "\n";
  }
  LogTail tail(path, 1000);
  const auto lines = tail.newLines();
  ASSERT_FALSE(lines.empty());
  EXPECT_LT(lines.size(), 100u);
  EXPECT_EQ(lines.front().rfind("[world] line ", 0), 0u);  // a whole line
  EXPECT_EQ(lines.back(), "[world] line 9999");
  std::filesystem::remove(path);
}

TEST(LogTail, SplitsTheProcessName) {
  EXPECT_EQ(splitProcessLine("[vision] 3 objects").process, "vision");
  EXPECT_EQ(splitProcessLine("[vision] 3 objects").text, "3 objects");
  EXPECT_EQ(splitProcessLine("plain").process, "");
  EXPECT_EQ(splitProcessLine("plain").text, "plain");
}

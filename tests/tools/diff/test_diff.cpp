// beft-diff against copies of a recorded run (peek, 6 ticks): identical, one
// message changed, one extra, one missing, run ids in the channel names, bad
// input. Each difference is named by its channel and index.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lib/wire/log_reader.hpp"

namespace {

const std::string kRun = std::string(BEFT_SOURCE_DIR) + "/tests/system/data/peek_6_ticks.lcmlog";

struct Result {
  int exit_code = -1;
  std::string output;
};

Result diff(const std::string& arguments) {
  Result result;
  FILE* pipe = popen((std::string(BEFT_DIFF_BINARY) + " " + arguments + " 2>&1").c_str(), "r");
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::vector<beft::wire::LogEvent> readEvents(const std::string& path) {
  beft::wire::LogReader reader(path);
  std::vector<beft::wire::LogEvent> events;
  beft::wire::LogEvent event;
  while (reader.next(event)) events.push_back(event);
  return events;
}

// The copies this program wrote (about 0.9 MB each): removed when it ends
// if every test passed, kept to look at if one failed.
std::vector<std::string>& writtenCopies() {
  static std::vector<std::string> paths;
  return paths;
}
class RemoveWrittenCopies : public testing::Environment {
 public:
  void TearDown() override {
    if (!testing::UnitTest::GetInstance()->Passed()) return;
    for (const std::string& path : writtenCopies()) std::remove(path.c_str());
  }
};
testing::Environment* const kRemoveWrittenCopies = testing::AddGlobalTestEnvironment(new RemoveWrittenCopies);

// A copy of the recorded run, each event changed (or dropped, or doubled) by `edit`.
using Edit = std::function<std::vector<beft::wire::LogEvent>(beft::wire::LogEvent event, int index_in_channel)>;
std::string writeCopy(const std::string& name, const Edit& edit) {
  const std::string path = testing::TempDir() + "/diff_" + name + "_" + std::to_string(getpid()) + ".lcmlog";
  writtenCopies().push_back(path);
  lcm::LogFile log(path, "w");
  std::map<std::string, int> seen;
  int64_t number = 0;
  for (const auto& original : readEvents(kRun)) {
    for (auto& event : edit(original, seen[original.channel]++)) {
      lcm::LogEvent out{};
      out.eventnum = number++;
      out.timestamp = event.timestamp;
      out.channel = event.channel;
      out.datalen = static_cast<int32_t>(event.data.size());
      out.data = event.data.data();
      EXPECT_EQ(log.writeEvent(&out), 0);
    }
  }
  return path;
}

std::vector<beft::wire::LogEvent> unchanged(beft::wire::LogEvent event, int) { return {event}; }

TEST(Diff, ALogIsIdenticalToItsCopy) {
  const auto result = diff(kRun + " " + writeCopy("copy", unchanged));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("identical"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("96 data messages"), std::string::npos) << result.output;
}

TEST(Diff, OneChangedByteInOneDataMessageIsNamed) {
  const std::string changed = writeCopy("changed", [](beft::wire::LogEvent event, int index) {
    if (event.channel == "VISION" && index == 3) event.data[event.data.size() - 1] ^= 0x01;
    return std::vector<beft::wire::LogEvent>{event};
  });
  const auto result = diff(kRun + " " + changed);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("VISION message #3 (tick 3"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("in " + changed + " (#3):"), std::string::npos) << result.output;
}

TEST(Diff, AnExtraMessageIsNamed) {
  const std::string extra = writeCopy("extra", [](beft::wire::LogEvent event, int index) {
    if (event.channel == "ROBOT_STATE" && index == 4) return std::vector<beft::wire::LogEvent>{event, event};
    return std::vector<beft::wire::LogEvent>{event};
  });
  const auto result = diff(kRun + " " + extra);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("ROBOT_STATE message #5 (tick 4"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("an extra message"), std::string::npos) << result.output;
}

TEST(Diff, AMissingMessageIsNamed) {
  const std::string missing = writeCopy("missing", [](beft::wire::LogEvent event, int index) {
    if (event.channel == "TASK_STACK" && index == 2) return std::vector<beft::wire::LogEvent>{};
    return std::vector<beft::wire::LogEvent>{event};
  });
  const auto result = diff(kRun + " " + missing);
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("TASK_STACK message #2 (tick 2"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("missing from " + missing), std::string::npos) << result.output;
}

// Two processes' messages of one tick reach the recorder in the network's
// order; the comparison ranks them by their bytes, so that order is not a
// difference, while a changed or missing one still is.
TEST(Diff, MessagesOfOneUtimeMatchWhateverTheirLogOrder) {
  const auto twin = [](beft::wire::LogEvent event) {
    event.data[event.data.size() - 1] ^= 0x01;
    return event;
  };
  const std::string in_order = writeCopy("one_utime_a", [&](beft::wire::LogEvent event, int index) {
    if (event.channel == "VISION" && index == 3) return std::vector<beft::wire::LogEvent>{event, twin(event)};
    return std::vector<beft::wire::LogEvent>{event};
  });
  const std::string swapped = writeCopy("one_utime_b", [&](beft::wire::LogEvent event, int index) {
    if (event.channel == "VISION" && index == 3) return std::vector<beft::wire::LogEvent>{twin(event), event};
    return std::vector<beft::wire::LogEvent>{event};
  });
  const auto same = diff(in_order + " " + swapped);
  EXPECT_EQ(same.exit_code, 0) << same.output;
  const auto against_run = diff(kRun + " " + swapped);
  EXPECT_EQ(against_run.exit_code, 1) << against_run.output;
  EXPECT_NE(against_run.output.find("VISION message #"), std::string::npos) << against_run.output;
}

TEST(Diff, RunIdsInChannelNamesAreLeftOut) {
  const std::string with_run = writeCopy("run_id", [](beft::wire::LogEvent event, int) {
    event.channel += "@1f3a";
    return std::vector<beft::wire::LogEvent>{event};
  });
  const auto result = diff(with_run + " " + kRun);
  EXPECT_EQ(result.exit_code, 0) << result.output;
}

TEST(Diff, AllListsEveryDifferenceAndChannelRestricts) {
  const std::string changed = writeCopy("two_changes", [](beft::wire::LogEvent event, int index) {
    if ((event.channel == "VISION" || event.channel == "GEOMETRY") && index == 1) event.data.back() ^= 0x01;
    return std::vector<beft::wire::LogEvent>{event};
  });
  const auto all = diff(kRun + " " + changed + " --all");
  EXPECT_EQ(all.exit_code, 1) << all.output;
  EXPECT_NE(all.output.find("VISION message #1"), std::string::npos) << all.output;
  EXPECT_NE(all.output.find("GEOMETRY message #1"), std::string::npos) << all.output;
  EXPECT_NE(all.output.find("2 differences"), std::string::npos) << all.output;
  const auto other_channel = diff(kRun + " " + changed + " --channel ROBOT_STATE");
  EXPECT_EQ(other_channel.exit_code, 0) << other_channel.output;
}

TEST(Diff, BadInputExitsWithTwoAndSaysWhy) {
  const auto missing = diff(kRun + " /nonexistent/run.lcmlog");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("cannot read /nonexistent/run.lcmlog: No such file or directory"), std::string::npos)
      << missing.output;
  const auto not_a_log = diff(kRun + " " + std::string(BEFT_SOURCE_DIR) + "/README.md");
  EXPECT_EQ(not_a_log.exit_code, 2);
  EXPECT_NE(not_a_log.output.find("README.md: not an LCM log"), std::string::npos) << not_a_log.output;
  const auto not_data = diff(kRun + " " + kRun + " --channel FIRE");
  EXPECT_EQ(not_data.exit_code, 2);
  EXPECT_NE(not_data.output.find("--channel FIRE: not a data channel"), std::string::npos) << not_data.output;
  EXPECT_EQ(diff("--help").exit_code, 0);
  EXPECT_EQ(diff(kRun).exit_code, 2);
}

}  // namespace

// A mission spread over two machines: two network namespaces joined by a
// virtual Ethernet link, the simulation side (blackboard, planner, world,
// arbiter, recorder) on one and the experts and task executor on the other,
// LCM multicast with ttl=1 between them. The run must write exactly the
// messages of the same run on one machine. Needs root and `ip netns`; skipped,
// with the reason, where they are missing.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "tests/system/run_support.hpp"
#include "tests/system/two_hosts.hpp"

using namespace beft::system_test;

namespace {

constexpr int kTicks = 150;

// The run ids of the launchers' "started N processes on URL as run ID" lines, in order.
std::vector<std::string> runIdsStarted(const std::string& output) {
  std::vector<std::string> ids;
  const std::string marker = " as run ";
  for (auto at = output.find(marker); at != std::string::npos; at = output.find(marker, at + 1)) {
    const auto start = at + marker.size();
    ids.push_back(output.substr(start, output.find_first_of(" \n", start) - start));
  }
  return ids;
}

class TwoHostsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why_not;
    hosts_ = TwoHosts::create(why_not);
    if (!hosts_) GTEST_SKIP() << why_not;
  }
  void TearDown() override { hosts_.reset(); }

  std::unique_ptr<TwoHosts> hosts_;
};

TEST_F(TwoHostsTest, ExpertsOnAnotherMachineWriteTheMessagesOfALocalRun) {
  const std::string dir = makeTempDir("distributed");
  DistributedMission mission;
  mission.bin_dir = binDir();
  mission.source_dir = sourceDir();
  mission.dir = dir;
  mission.seed = 7;
  mission.max_ticks = kTicks;
  const auto distributed = runCommand(distributedMissionCommand(*hosts_, mission), 300);
  ASSERT_EQ(distributed.exit_code, 0) << distributed.output;
  EXPECT_NE(distributed.output.find("not starting vision: it runs on host 'robot'"), std::string::npos)
      << distributed.output;
  EXPECT_NE(distributed.output.find("not starting world: it runs on host 'local'"), std::string::npos)
      << distributed.output;
  EXPECT_NE(distributed.output.find("run FINISHED: finished after " + std::to_string(kTicks) + " ticks"),
            std::string::npos)
      << distributed.output;
  // One run: the robot's launch joined the run the arbiter's launch drew.
  const std::vector<std::string> runs = runIdsStarted(distributed.output);
  ASSERT_EQ(runs.size(), 2u) << distributed.output;
  EXPECT_EQ(runs[0], runs[1]) << distributed.output;
  EXPECT_NE(distributed.output.find("joining run " + runs[0] + " (arbiter pid"), std::string::npos)
      << distributed.output;

  const auto local = runCommand(binDir() + "/beft-run " + sourceDir() + "/scenarios/yard.xml --seed 7 --max-ticks " +
                                    std::to_string(kTicks) + " --no-report --out " + dir + "/local",
                                300);
  ASSERT_EQ(local.exit_code, 0) << local.output;
  const DataComparison comparison =
      compareDataMessages(readLog(dir + "/local/run.lcmlog"), readLog(dir + "/run.lcmlog"));
  ASSERT_GT(comparison.expected, static_cast<std::size_t>(kTicks * 15));
  EXPECT_TRUE(comparison.identical()) << comparison.first_difference;
}

}  // namespace

// A mission spread over two machines: two network namespaces joined by a
// virtual Ethernet link, the simulation side (blackboard, planner, world,
// arbiter, recorder) on one and the experts and task executor on the other,
// LCM multicast with ttl=1 between them. The run must write exactly the
// messages of the same run on one machine. Needs root and `ip netns`; skipped,
// with the reason, where they are missing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

#include "tests/system/run_support.hpp"

using namespace beft::system_test;

namespace {

constexpr int kTicks = 150;

class TwoHosts : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string tag = std::to_string(getpid() % 100000);
    sim_ = "beft_sim_" + tag;
    robot_ = "beft_robot_" + tag;
    if (geteuid() != 0) GTEST_SKIP() << "needs root to create network namespaces";
    const std::string link_sim = "bsim" + tag, link_robot = "brob" + tag;  // at most 15 characters
    const auto setup = runCommand(
        "set -e; ip netns add " + sim_ + "; ip netns add " + robot_ + "; ip link add " + link_sim +
            " type veth peer name " + link_robot + "; ip link set " + link_sim + " netns " + sim_ +
            "; ip link set " + link_robot + " netns " + robot_ + "; ip -n " + sim_ + " addr add 10.231.0.1/24 dev " +
            link_sim + "; ip -n " + robot_ + " addr add 10.231.0.2/24 dev " + link_robot + "; for ns in " + sim_ +
            " " + robot_ + "; do ip -n $ns link set lo up; done; ip -n " + sim_ + " link set " + link_sim +
            " up; ip -n " + robot_ + " link set " + link_robot + " up; ip -n " + sim_ +
            " route add 224.0.0.0/4 dev " + link_sim + "; ip -n " + robot_ + " route add 224.0.0.0/4 dev " +
            link_robot,
        30);
    created_ = true;
    if (setup.exit_code != 0) GTEST_SKIP() << "cannot create two linked network namespaces here:\n" << setup.output;
  }
  void TearDown() override {
    if (!created_) return;
    // Anything still running in them (a side that missed the end of the run) goes too.
    for (const auto& ns : {sim_, robot_})
      runCommand("ip netns pids " + ns + " 2>/dev/null | xargs -r kill -9; ip netns del " + ns + " 2>/dev/null", 30);
  }

  std::string sim_, robot_;
  bool created_ = false;
};

TEST_F(TwoHosts, ExpertsOnAnotherMachineWriteTheMessagesOfALocalRun) {
  const std::string dir = makeTempDir("distributed");
  // Each namespace has ports of its own: the default port cannot collide.
  const std::string url = "'udpm://239.255.76.67:7667?ttl=1&recv_buf_size=8388608'";
  const std::string launch = binDir() + "/beft-launch scenarios/launch/mission.xml --set expert_host=robot --set seed=7 "
                             "--set max_ticks=" + std::to_string(kTicks) + " --lcm-url " + url;
  const auto distributed = runCommand("cd " + sourceDir() + " && (ip netns exec " + robot_ + " " + launch +
                                          " --host robot > " + dir + "/robot.log 2>&1 &) && ip netns exec " + sim_ +
                                          " " + launch + " --record " + dir + "/run.lcmlog > " + dir +
                                          "/sim.log 2>&1; status=$?; sleep 1; cat " + dir + "/sim.log " + dir +
                                          "/robot.log; exit $status",
                                      300);
  ASSERT_EQ(distributed.exit_code, 0) << distributed.output;
  EXPECT_NE(distributed.output.find("not starting vision: it runs on host 'robot'"), std::string::npos)
      << distributed.output;
  EXPECT_NE(distributed.output.find("not starting world: it runs on host 'local'"), std::string::npos)
      << distributed.output;
  EXPECT_NE(distributed.output.find("run FINISHED: finished after " + std::to_string(kTicks) + " ticks"),
            std::string::npos)
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

// The mission of test_distributed over a link that loses datagrams: each of
// the two namespaces drops a share P of the UDP datagrams it receives over
// the link (iptables' statistic match), so messages are lost both ways, and
// loss repair (lib/transport: envelopes, repair requests, senders' states)
// must get every one of them through. The run completes, writes exactly the
// data messages of the local run of the same seed, and its recorder says the
// log is complete (RECORD_STATUS, final). The ticks per second and what was
// repaired are printed, not asserted (the machine is shared). Needs root,
// `ip netns` and iptables; skipped, with the reason, where they are missing.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <beft/record_status_t.hpp>

#include "tests/system/run_support.hpp"
#include "tests/system/two_hosts.hpp"

using namespace beft::system_test;

namespace {

constexpr int kTicks = 150;
constexpr uint64_t kSeed = 7;

// The local run of the same seed, made once for every loss rate.
struct LocalRun {
  std::vector<LoggedMessage> log;
  double ticks_per_s = 0;
};

const LocalRun& localRun() {
  static std::optional<LocalRun> run;
  if (run) return *run;
  const std::string dir = makeTempDir("lossy_local");
  const auto local = runCommand(binDir() + "/beft-run " + sourceDir() + "/scenarios/yard.xml --seed " +
                                    std::to_string(kSeed) + " --max-ticks " + std::to_string(kTicks) + " --out " + dir,
                                300);
  if (local.exit_code != 0) throw std::runtime_error("the local run failed:\n" + local.output);
  run = LocalRun{readLog(dir + "/run.lcmlog"), readJson(dir + "/report.json").value("ticks_per_s", 0.0)};
  return *run;
}

// The first line of `output` that holds `text`; "" if none.
std::string lineWith(const std::string& output, const std::string& text) {
  const auto at = output.find(text);
  if (at == std::string::npos) return "";
  const auto start = output.rfind('\n', at);
  const auto begin = start == std::string::npos ? 0 : start + 1;
  return output.substr(begin, output.find('\n', at) - begin);
}

// The recorder's last account of its log.
std::optional<beft::record_status_t> lastRecordStatus(const std::vector<LoggedMessage>& log) {
  const auto statuses = messagesOn<beft::record_status_t>(log, "RECORD_STATUS");
  if (statuses.empty()) return std::nullopt;
  return statuses.back();
}

// The ticks per second beft-report finds in dir/run.lcmlog; 0 if it cannot say.
double ticksPerSecondOf(const std::string& dir) {
  const auto report =
      runCommand(binDir() + "/beft-report " + dir + "/run.lcmlog --quiet --out " + dir + "/report", 120);
  return report.exit_code == 0 ? readJson(dir + "/report/report.json").value("ticks_per_s", 0.0) : 0.0;
}

class LossyLink : public ::testing::TestWithParam<double> {
 protected:
  void SetUp() override {
    std::string why_not;
    hosts_ = TwoHosts::create(why_not);
    if (!hosts_) GTEST_SKIP() << why_not;
    why_not = hosts_->dropIncoming(GetParam());
    if (!why_not.empty()) GTEST_SKIP() << why_not;
  }
  void TearDown() override { hosts_.reset(); }

  std::unique_ptr<TwoHosts> hosts_;
};

TEST_P(LossyLink, RunCompletesWithTheMessagesOfALocalRunAndACompleteLog) {
  const double loss = GetParam();
  const std::string dir = makeTempDir("lossy_link");
  DistributedMission mission;
  mission.bin_dir = binDir();
  mission.source_dir = sourceDir();
  mission.dir = dir;
  mission.seed = kSeed;
  mission.max_ticks = kTicks;
  const auto distributed = runCommand(distributedMissionCommand(*hosts_, mission), 400);
  const uint64_t dropped = hosts_->droppedDatagrams();
  ASSERT_EQ(distributed.exit_code, 0) << distributed.output;
  EXPECT_GT(dropped, 0u) << "the link lost nothing: the run says nothing about loss";
  ASSERT_NE(distributed.output.find("run FINISHED: finished after " + std::to_string(kTicks) + " ticks"),
            std::string::npos)
      << distributed.output;

  const auto log = readLog(dir + "/run.lcmlog");
  const auto status = lastRecordStatus(log);
  ASSERT_TRUE(status.has_value()) << "no RECORD_STATUS in " << dir << "/run.lcmlog";
  EXPECT_TRUE(status->final) << "the recorder's last account is not its final one";
  EXPECT_TRUE(status->complete) << status->lost << " message(s) lost, " << status->joined_late
                                << " stream(s) joined late; the recorder: "
                                << lineWith(distributed.output, "loss repair: ");
  EXPECT_EQ(status->lost, 0);

  const LocalRun& local = localRun();
  const DataComparison comparison = compareDataMessages(local.log, log);
  ASSERT_GT(comparison.expected, static_cast<std::size_t>(kTicks * 15));
  EXPECT_TRUE(comparison.identical()) << comparison.first_difference;

  std::printf("[lossy link] %.0f %% loss each way: %.1f ticks/s (local run %.1f); %llu datagrams dropped; "
              "the recorder repaired %lld message(s), lost %lld; run in %s\n",
              loss * 100, ticksPerSecondOf(dir), local.ticks_per_s, static_cast<unsigned long long>(dropped),
              static_cast<long long>(status->repaired), static_cast<long long>(status->lost), dir.c_str());
}

// 10 % each way runs in `./beft bench faults`: there the recorder now and
// then gives up on one message near the run's end (1 of 877 missed in one
// clean-clone run), which leaves its log incomplete.
INSTANTIATE_TEST_SUITE_P(LossEachWay, LossyLink, ::testing::Values(0.01, 0.05, 0.10),
                         [](const ::testing::TestParamInfo<double>& info) {
                           return std::to_string(static_cast<int>(info.param * 100 + 0.5)) + "Percent";
                         });

}  // namespace

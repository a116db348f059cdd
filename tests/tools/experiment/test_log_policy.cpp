// Which finished episodes keep their run log (log_policy.hpp): by default
// those that did not succeed; with --keep-logs all, every one.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "tools/experiment/log_policy.hpp"

using namespace beft::experiment;
namespace fs = std::filesystem;

namespace {

class LogPolicyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("beft_log_policy_" + std::to_string(getpid()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  // A finished episode's folder: its report (raw text) and a log.
  EpisodeState finished(const std::string& report, Status status = Status::done) {
    std::ofstream(folder_ / "report.json") << report;
    std::ofstream(folder_ / kRunLog) << "log bytes";
    EpisodeState state;
    state.status = status;
    return state;
  }
  bool logKept() const { return fs::exists(folder_ / kRunLog); }

  fs::path folder_;
};

}  // namespace

TEST_F(LogPolicyTest, ASuccessfulEpisodeLosesItsLogUnlessAllAreKept) {
  const std::string success = R"({"completed": true, "collisions": 0, "sim_time_s": 30})";
  EXPECT_FALSE(applyLogPolicy(folder_.string(), finished(success), KeepLogs::all));
  EXPECT_TRUE(logKept());
  EXPECT_TRUE(applyLogPolicy(folder_.string(), finished(success), KeepLogs::unsuccessful));
  EXPECT_FALSE(logKept());
}

TEST_F(LogPolicyTest, AnEpisodeThatDidNotSucceedKeepsItsLog) {
  const std::pair<std::string, Status> unsuccessful[] = {
      {R"({"completed": false, "collisions": 0})", Status::done},
      {R"({"completed": true, "collisions": 1})", Status::done},
      {R"({"completed": true, "collisions": 0})", Status::failed},
      {R"({"completed": true})", Status::done},
      {R"({"completed": "yes", "collisions": 0})", Status::done},
      {R"({"completed": tru)", Status::done},
  };
  for (const auto& [report, status] : unsuccessful) {
    EXPECT_FALSE(applyLogPolicy(folder_.string(), finished(report, status), KeepLogs::unsuccessful)) << report;
    EXPECT_TRUE(logKept()) << report;
  }
}

TEST(LogPolicy, NamesReadBackAndOthersAreRefused) {
  for (const KeepLogs keep : {KeepLogs::unsuccessful, KeepLogs::all}) EXPECT_EQ(keepLogsNamed(nameOf(keep)), keep);
  EXPECT_FALSE(keepLogsNamed("failed").has_value());
}

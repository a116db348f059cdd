// The local pool with episodes that are small shell scripts: each writes a
// report with its simulated time and notes when it started and ended, so the
// order of events, not their timing, is what the tests check.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tools/experiment/episode_run.hpp"
#include "tools/experiment/local_pool.hpp"

namespace beft::experiment {
namespace {

namespace fs = std::filesystem;

class LocalPoolTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char name[] = "/tmp/beft_local_pool_XXXXXX";
    ASSERT_NE(mkdtemp(name), nullptr);
    dir_ = name;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // An episode that notes "start ID" and "end ID" in the shared events file
  // around a short sleep, and reports `simulated_s` of simulated time.
  PoolJob episode(const std::string& id, double simulated_s) const {
    const std::string events = (dir_ / "events.txt").string();
    std::ostringstream script;
    script << "echo start " << id << " >> '" << events << "'; sleep 0.2; "
           << "echo '{\"sim_time_s\": " << simulated_s << "}' > report.json; echo end " << id << " >> '" << events
           << "'";
    const std::string folder = (dir_ / id).string();
    return {id, folder, {"/bin/sh", "-c", "cd '" + folder + "' && " + script.str()}, {id}};
  }
  std::vector<std::string> events() const {
    std::ifstream in(dir_ / "events.txt");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }

  fs::path dir_;
  std::function<void(const std::string&)> quiet = [](const std::string&) {};
};

TEST_F(LocalPoolTest, TheFirstEpisodeRunsAloneThenThePoolForOneJobsPaceAndTheSpeedUp) {
  const std::vector<PoolJob> jobs = {episode("a", 10), episode("b", 20), episode("c", 30), episode("d", 40)};
  const PoolOutcome outcome = runLocalPool(jobs, 2, quiet);
  EXPECT_EQ(outcome.done, 4);
  const auto seen = events();
  ASSERT_EQ(seen.size(), 8u);
  EXPECT_EQ(seen[0], "start a");
  EXPECT_EQ(seen[1], "end a") << "another episode started beside the one that measures one job";
  EXPECT_EQ(outcome.alone_id, "a");
  EXPECT_EQ(outcome.alone.episodes, 1);
  EXPECT_DOUBLE_EQ(outcome.alone.simulated_s, 10);
  EXPECT_EQ(outcome.pooled.episodes, 3);
  EXPECT_DOUBLE_EQ(outcome.pooled.simulated_s, 90);
  EXPECT_TRUE(outcome.hasSpeedUp());
  EXPECT_GT(outcome.alone.wall_s, 0);
  EXPECT_GT(outcome.pooled.wall_s, 0);
  EXPECT_LE(outcome.alone.wall_s + outcome.pooled.wall_s, outcome.wall_s + 1e-6);
  // The episode's own record keeps its simulated time.
  EXPECT_DOUBLE_EQ(readEpisodeState(jobs[3].folder).simulated_s, 40);
}

TEST_F(LocalPoolTest, NoEpisodeAloneWhenThePoolHasNoMoreEpisodesThanJobs) {
  const std::vector<PoolJob> jobs = {episode("a", 10), episode("b", 20)};
  const PoolOutcome outcome = runLocalPool(jobs, 2, quiet);
  EXPECT_EQ(outcome.done, 2);
  EXPECT_FALSE(outcome.hasSpeedUp());
  const auto seen = events();
  ASSERT_EQ(seen.size(), 4u);
  EXPECT_EQ(seen[0].substr(0, 5), "start");
  EXPECT_EQ(seen[1].substr(0, 5), "start") << "both episodes run at once";
}

TEST_F(LocalPoolTest, OneJobRunsOneAfterAnotherWithoutASpeedUp) {
  const PoolOutcome outcome = runLocalPool({episode("a", 10), episode("b", 20), episode("c", 30)}, 1, quiet);
  EXPECT_EQ(outcome.done, 3);
  EXPECT_FALSE(outcome.hasSpeedUp());
  EXPECT_EQ(events(), (std::vector<std::string>{"start a", "end a", "start b", "end b", "start c", "end c"}));
}

}  // namespace
// A damaged episode.json (fields of another type) reads as an episode not
// done, to run again, never as an exception that ends the experiment.
TEST(EpisodeState, ADamagedStateFileReadsAsNotDone) {
  const fs::path folder = fs::temp_directory_path() / ("beft_episode_state_" + std::to_string(getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / kEpisodeFile) << R"({"status": 1, "exit_code": "0", "reason": [], "command": ["beft-run", 3], "log": null})";
  EpisodeState state;
  EXPECT_NO_THROW(state = readEpisodeState(folder.string()));
  fs::remove_all(folder);
  EXPECT_EQ(state.status, Status::failed);
  EXPECT_EQ(state.exit_code, 0);
  EXPECT_EQ(state.reason, "");
  EXPECT_EQ(state.command, (std::vector<std::string>{"beft-run"}));
  EXPECT_FALSE(state.log_removed);
}

}  // namespace beft::experiment

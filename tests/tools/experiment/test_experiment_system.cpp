// A tiny experiment of real runs (two short episodes of the yard): run whole,
// run again interrupted halfway and resumed, which runs only the missing
// episode and gives the same rows; an episode that fails is recorded with its
// reason and not run again (unless asked), nor taken for this experiment's
// once the file's options change. Without Slurm's commands, --slurm is refused.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Finished {
  int code = -1;
  std::string output;
};

class ExperimentSystemTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("beft_experiment_system_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "tiny.xml") << "<experiment max_ticks=\"300\">\n  <scenario file=\"" BEFT_SOURCE_DIR
                                        "/scenarios/yard.xml\"/>\n  <seeds values=\"1-2\"/>\n</experiment>\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  pid_t start(const std::string& out, const std::string& jobs, const std::string& file = "tiny.xml",
              std::vector<std::string> more = {}) {
    std::vector<std::string> args = {BEFT_EXPERIMENT_BINARY, (dir_ / file).string(), "--out", (dir_ / out).string(),
                                     "--jobs", jobs};
    args.insert(args.end(), more.begin(), more.end());
    const pid_t pid = fork();
    if (pid == 0) {
      const std::string output = (dir_ / (out + ".txt")).string();
      if (!freopen(output.c_str(), "w", stdout) || !freopen(output.c_str(), "a", stderr)) _exit(126);
      std::vector<char*> argv;
      for (auto& arg : args) argv.push_back(arg.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
    return pid;
  }
  Finished wait(pid_t pid, const std::string& out) {
    int status = 0;
    waitpid(pid, &status, 0);
    std::ifstream in(dir_ / (out + ".txt"));
    std::stringstream text;
    text << in.rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
  }
  Finished run(const std::string& out, const std::string& jobs, const std::string& file = "tiny.xml") {
    return wait(start(out, jobs, file), out);
  }
  // episodes.csv without the wall time, the one column that differs between runs.
  std::vector<std::string> rows(const std::string& out) {
    std::ifstream in(dir_ / out / "episodes.csv");
    std::vector<std::string> lines;
    int wall_column = -1;
    for (std::string line; std::getline(in, line);) {
      std::vector<std::string> fields;
      std::stringstream split(line);
      for (std::string field; std::getline(split, field, ',');) fields.push_back(field);
      if (wall_column < 0)
        for (size_t i = 0; i < fields.size(); ++i)
          if (fields[i] == "wall_time_s") wall_column = static_cast<int>(i);
      if (wall_column >= 0 && wall_column < static_cast<int>(fields.size())) fields.erase(fields.begin() + wall_column);
      std::string row;
      for (const auto& f : fields) row += f + ",";
      lines.push_back(row);
    }
    return lines;
  }
  static std::string text(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream all;
    all << in.rdbuf();
    return all.str();
  }
  bool recorded(const std::string& out, const std::string& episode) {
    return fs::exists(dir_ / out / "episodes" / episode / "episode.json");
  }

  fs::path dir_;
};

TEST_F(ExperimentSystemTest, InterruptedAndResumedGivesTheSameRows) {
  const Finished whole = run("whole", "2");
  ASSERT_EQ(whole.code, 0) << whole.output;
  const auto expected = rows("whole");
  ASSERT_EQ(expected.size(), 3u) << whole.output;
  EXPECT_NE(expected[1].find("yard_seed-1,yard,1,done,,1,"), std::string::npos) << expected[1];
  // Both completed: by default their logs go, and episode.json says so.
  for (const char* episode : {"yard_seed-1", "yard_seed-2"}) {
    EXPECT_FALSE(fs::exists(dir_ / "whole" / "episodes" / episode / "run.lcmlog")) << episode;
    EXPECT_NE(text(dir_ / "whole" / "episodes" / episode / "episode.json").find("\"log\": \"removed"),
              std::string::npos) << episode;
  }
  EXPECT_NE(whole.output.find("run logs: removed for 2 episode(s) that succeeded"), std::string::npos) << whole.output;

  // One job at a time, stopped once the first episode is done: the second is left missing.
  const pid_t pid = start("resumed", "1");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!recorded("resumed", "yard_seed-1") && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  kill(pid, SIGTERM);
  const Finished interrupted = wait(pid, "resumed");
  EXPECT_EQ(interrupted.code, 130) << interrupted.output;
  ASSERT_TRUE(recorded("resumed", "yard_seed-1")) << interrupted.output;
  ASSERT_FALSE(recorded("resumed", "yard_seed-2")) << interrupted.output;
  const auto first_done = fs::last_write_time(dir_ / "resumed" / "episodes" / "yard_seed-1" / "report.json");

  const Finished resumed = run("resumed", "2");
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("1 done, 0 failed, 1 to run"), std::string::npos) << resumed.output;
  EXPECT_EQ(resumed.output.find("done yard_seed-1 "), std::string::npos) << resumed.output;
  EXPECT_EQ(fs::last_write_time(dir_ / "resumed" / "episodes" / "yard_seed-1" / "report.json"), first_done);
  EXPECT_EQ(rows("resumed"), expected);
  for (const char* written : {"summary.json", "summary.csv", "success.png", "time_to_find.png"})
    EXPECT_GT(fs::file_size(dir_ / "resumed" / written), 100u) << written;
  EXPECT_NE(resumed.output.find("100% ("), std::string::npos) << resumed.output;

  const Finished again = run("resumed", "2");  // nothing left
  EXPECT_EQ(again.code, 0);
  EXPECT_NE(again.output.find("2 done, 0 failed, 0 to run"), std::string::npos) << again.output;
}

TEST_F(ExperimentSystemTest, AnEpisodeThatDidNotCompleteKeepsItsLogAndAllKeepEveryOne) {
  std::ofstream(dir_ / "short.xml") << "<experiment max_ticks=\"20\">\n  <scenario file=\"" BEFT_SOURCE_DIR
                                       "/scenarios/yard.xml\"/>\n</experiment>\n";
  const Finished cut_short = run("short", "1", "short.xml");
  ASSERT_EQ(cut_short.code, 0) << cut_short.output;
  ASSERT_NE(rows("short")[1].find("done,,0,"), std::string::npos) << rows("short")[1];  // not completed
  EXPECT_GT(fs::file_size(dir_ / "short" / "episodes" / "yard" / "run.lcmlog"), 1000u);

  std::ofstream(dir_ / "one.xml") << "<experiment max_ticks=\"300\">\n  <scenario file=\"" BEFT_SOURCE_DIR
                                     "/scenarios/yard.xml\"/>\n</experiment>\n";
  const Finished kept = wait(start("one", "1", "one.xml", {"--keep-logs", "all"}), "one");
  ASSERT_EQ(kept.code, 0) << kept.output;
  ASSERT_NE(rows("one")[1].find("done,,1,"), std::string::npos) << rows("one")[1];  // completed
  EXPECT_GT(fs::file_size(dir_ / "one" / "episodes" / "yard" / "run.lcmlog"), 1000u);
  EXPECT_EQ(kept.output.find("run logs: removed"), std::string::npos) << kept.output;
}

TEST_F(ExperimentSystemTest, AFailedEpisodeIsRecordedWithItsReasonAndNotRunAgain) {
  std::ofstream(dir_ / "bad.xml") << "<experiment max_ticks=\"20\">\n  <scenario file=\"" BEFT_SOURCE_DIR
                                     "/scenarios/yard.xml\"/>\n  <set name=\"no_such_arg\" values=\"1\"/>\n"
                                     "</experiment>\n";
  const Finished failed = run("bad", "1", "bad.xml");
  EXPECT_EQ(failed.code, 1);
  EXPECT_NE(failed.output.find("FAILED yard_no_such_arg-1"), std::string::npos) << failed.output;
  EXPECT_NE(rows("bad")[1].find("failed,\"[run] error:"), std::string::npos) << rows("bad")[1];
  EXPECT_NE(rows("bad")[1].find("declares no <arg name="), std::string::npos) << rows("bad")[1];
  const Finished again = run("bad", "1", "bad.xml");
  EXPECT_EQ(again.code, 1);
  EXPECT_NE(again.output.find("0 done, 1 failed (not run again without --retry-failed), 0 to run"),
            std::string::npos) << again.output;
  const Finished retried = wait(start("bad", "1", "bad.xml", {"--retry-failed"}), "bad");
  EXPECT_NE(retried.output.find("0 done, 1 failed, 1 to run"), std::string::npos) << retried.output;

  // Other options than those it ran with: the episode is not this experiment's any more.
  std::ofstream(dir_ / "bad.xml") << "<experiment max_ticks=\"30\">\n  <scenario file=\"" BEFT_SOURCE_DIR
                                     "/scenarios/yard.xml\"/>\n  <set name=\"no_such_arg\" values=\"1\"/>\n"
                                     "</experiment>\n";
  const Finished changed = run("bad", "1", "bad.xml");
  EXPECT_NE(changed.output.find("yard_no_such_arg-1 was run with other options"), std::string::npos) << changed.output;
  EXPECT_NE(changed.output.find("0 done, 0 failed, 1 to run"), std::string::npos) << changed.output;
}

TEST_F(ExperimentSystemTest, SlurmWithoutItsCommandsIsRefused) {
  const pid_t pid = fork();
  if (pid == 0) {  // a PATH without sbatch and squeue
    setenv("PATH", (dir_ / "empty").c_str(), 1);
    const std::string output = (dir_ / "no_slurm.txt").string();
    if (!freopen(output.c_str(), "w", stdout) || !freopen(output.c_str(), "a", stderr)) _exit(126);
    execl(BEFT_EXPERIMENT_BINARY, BEFT_EXPERIMENT_BINARY, (dir_ / "tiny.xml").c_str(), "--out",
          (dir_ / "no_slurm").c_str(), "--slurm", static_cast<char*>(nullptr));
    _exit(127);
  }
  const Finished refused = wait(pid, "no_slurm");
  EXPECT_EQ(refused.code, 2) << refused.output;
  EXPECT_NE(refused.output.find("--slurm needs Slurm's commands on PATH; not found: sbatch squeue"), std::string::npos)
      << refused.output;
  EXPECT_FALSE(fs::exists(dir_ / "no_slurm"));
}

}  // namespace

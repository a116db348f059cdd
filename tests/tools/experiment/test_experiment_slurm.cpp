// The same tiny experiment (two short episodes of the yard) on a Slurm
// cluster of one node that the test starts itself, and locally: the same
// rows but for the wall time; started again, the experiment submits nothing.
// Skipped (77) with the reason where the cluster cannot start: not root, or
// munge or Slurm's daemons missing or not coming up.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "slurm_cluster.hpp"

namespace {

namespace fs = std::filesystem;

struct Finished {
  int code = -1;
  std::string output;
};

// The experiment program with its output (stdout and stderr) kept.
Finished runExperiment(std::vector<std::string> args, const fs::path& output) {
  args.insert(args.begin(), BEFT_EXPERIMENT_BINARY);
  const pid_t pid = fork();
  if (pid == 0) {
    if (!freopen(output.c_str(), "w", stdout) || !freopen(output.c_str(), "a", stderr)) _exit(126);
    std::vector<char*> argv;
    for (auto& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  std::ifstream in(output);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

// episodes.csv without its column wall_time_s, the one that differs between runs.
std::vector<std::string> rowsWithoutWallTime(const fs::path& csv) {
  std::ifstream in(csv);
  std::vector<std::string> rows;
  int wall = -1;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::stringstream split(line);
    for (std::string field; std::getline(split, field, ',');) fields.push_back(field);
    for (size_t i = 0; wall < 0 && i < fields.size(); ++i)
      if (fields[i] == "wall_time_s") wall = static_cast<int>(i);
    if (wall >= 0 && wall < static_cast<int>(fields.size())) fields.erase(fields.begin() + wall);
    std::string row;
    for (const auto& field : fields) row += field + ",";
    rows.push_back(row);
  }
  return rows;
}

std::string readFile(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct TemporaryFolder {
  fs::path path;
  ~TemporaryFolder() { fs::remove_all(path); }
};

TEST(ExperimentOnSlurm, GivesTheLocalRowsAndResumesWithoutSubmitting) {
  const TemporaryFolder folder{fs::temp_directory_path() / ("beft_experiment_slurm_" + std::to_string(getpid()))};
  const fs::path& dir = folder.path;
  beft::test::SlurmCluster cluster;
  const std::string why = cluster.start(dir / "cluster");
  if (!why.empty()) GTEST_SKIP() << "no Slurm cluster of one node here: " << why;
  const fs::path work = dir / "experiment";
  fs::create_directories(work);
  const std::string file = (work / "tiny.xml").string();
  std::ofstream(file) << "<experiment max_ticks=\"150\">\n  <scenario file=\"" BEFT_SOURCE_DIR
                         "/scenarios/yard.xml\"/>\n  <seeds values=\"1-2\"/>\n</experiment>\n";
  const std::string slurm_out = (work / "slurm").string();
  const std::string partition = beft::test::SlurmCluster::kPartition;
  const std::vector<std::string> on_slurm = {file, "--out", slurm_out, "--slurm", "--partition", partition,
                                             "--time-limit", "5", "--mem", "1000"};

  std::vector<std::string> waited = on_slurm;
  waited.push_back("--slurm-wait");
  const Finished slurm = runExperiment(waited, work / "slurm.txt");
  ASSERT_EQ(slurm.code, 0) << slurm.output;
  EXPECT_NE(slurm.output.find("submitted job "), std::string::npos) << slurm.output;
  EXPECT_NE(slurm.output.find("2 task(s), one per episode (partition beft, time limit 5 min, memory 1000 MB"),
            std::string::npos)
      << slurm.output;
  EXPECT_NE(readFile(work / "slurm" / "slurm" / "job.sbatch").find("#SBATCH --array=0-1\n"), std::string::npos);
  const Finished local = runExperiment({file, "--out", (work / "local").string(), "--jobs", "2"}, work / "local.txt");
  ASSERT_EQ(local.code, 0) << local.output;
  const auto rows = rowsWithoutWallTime(work / "local" / "episodes.csv");
  ASSERT_EQ(rows.size(), 3u) << local.output;
  EXPECT_EQ(rowsWithoutWallTime(work / "slurm" / "episodes.csv"), rows) << slurm.output;

  // Everything done: started again, it submits nothing and gathers the same rows.
  const std::string job = readFile(work / "slurm" / "slurm" / "job.txt");
  const Finished again = runExperiment(on_slurm, work / "again.txt");
  EXPECT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find("2 done, 0 failed, 0 to run on Slurm"), std::string::npos) << again.output;
  EXPECT_EQ(again.output.find("submitted"), std::string::npos) << again.output;
  EXPECT_EQ(readFile(work / "slurm" / "slurm" / "job.txt"), job);
  EXPECT_EQ(rowsWithoutWallTime(work / "slurm" / "episodes.csv"), rows);
}

}  // namespace

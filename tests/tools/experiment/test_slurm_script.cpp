// The sbatch script of the missing episodes: one array task per episode, the
// limits asked for, each task the same command with its episode's id.
#include <gtest/gtest.h>

#include "tools/experiment/slurm_script.hpp"

namespace beft::experiment {
namespace {

BatchJob twoEpisodes() {
  return {"tiny run", "/shared/out",
          {"/opt/bin/beft-experiment", "/shared/it's.xml", "--out", "/shared/out", "--run-episode"},
          {"yard_seed-1", "yard_seed-2"}};
}

TEST(SlurmScript, OneTaskPerEpisodeWithTheLimitsAskedFor) {
  const std::string script = batchScript(twoEpisodes(), {"short", 30, 4000, 2});
  for (const char* line :
       {"#!/bin/bash\n", "#SBATCH --job-name=beft-tiny_run\n", "#SBATCH --array=0-1\n",
        "#SBATCH --chdir=\"/shared/out\"\n", "#SBATCH --output=slurm/task-%A_%a.txt\n", "#SBATCH --cpus-per-task=2\n",
        "#SBATCH --partition=short\n", "#SBATCH --time=30\n", "#SBATCH --mem=4000M\n",
        "ids=(\n  'yard_seed-1'\n  'yard_seed-2'\n)\n",
        "exec '/opt/bin/beft-experiment' '/shared/it'\\''s.xml' '--out' '/shared/out' '--run-episode' "
        "\"${ids[$SLURM_ARRAY_TASK_ID]}\"\n"})
    EXPECT_NE(script.find(line), std::string::npos) << line << "\nin\n" << script;
}

TEST(SlurmScript, LimitsNotGivenAreLeftToTheCluster) {
  const std::string script = batchScript(twoEpisodes(), {});
  for (const char* option : {"--partition", "--time", "--mem"})
    EXPECT_EQ(script.find(std::string("#SBATCH ") + option), std::string::npos) << option;
}

TEST(SlurmScript, ShellWords) {
  EXPECT_EQ(shellQuoted("plain"), "'plain'");
  EXPECT_EQ(shellQuoted("a b"), "'a b'");
  EXPECT_EQ(shellQuoted("it's"), "'it'\\''s'");
  EXPECT_EQ(shellQuoted(""), "''");
}

}  // namespace
}  // namespace beft::experiment

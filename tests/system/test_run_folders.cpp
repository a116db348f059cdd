// The system tests' run folders go when their program passed and stay,
// named, when it failed (run_folders.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "tests/system/run_support.hpp"

using namespace beft::system_test;

namespace {

// Runs the probe with the given environment; the folder it made.
std::string probeFolder(const std::string& environment, ProgramResult* result) {
  *result = runCommand(environment + " " + binDir() + "/run_folders_probe", 60);
  std::smatch made;
  if (!std::regex_search(result->output, made, std::regex("made (/tmp/beft_probe_\\S+)"))) return {};
  return made[1];
}

}  // namespace

TEST(RunFolders, APassingProgramRemovesItsFolders) {
  ProgramResult result;
  const std::string folder = probeFolder("env -u PROBE_FAIL -u BEFT_KEEP_TEST_DIRS", &result);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  ASSERT_FALSE(folder.empty()) << result.output;
  EXPECT_FALSE(std::filesystem::exists(folder));
}

TEST(RunFolders, AFailingProgramKeepsAndNamesThem) {
  ProgramResult result;
  const std::string folder = probeFolder("env -u BEFT_KEEP_TEST_DIRS PROBE_FAIL=1", &result);
  EXPECT_NE(result.exit_code, 0);
  ASSERT_FALSE(folder.empty()) << result.output;
  EXPECT_TRUE(std::filesystem::is_directory(folder));
  EXPECT_NE(result.output.find("run folder kept: " + folder), std::string::npos) << result.output;
  std::filesystem::remove_all(folder);
}

TEST(RunFolders, KeptOnRequestEvenWhenAllPassed) {
  ProgramResult result;
  const std::string folder = probeFolder("env -u PROBE_FAIL BEFT_KEEP_TEST_DIRS=1", &result);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  ASSERT_FALSE(folder.empty()) << result.output;
  EXPECT_TRUE(std::filesystem::is_directory(folder));
  std::filesystem::remove_all(folder);
}

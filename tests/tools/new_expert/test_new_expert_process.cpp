// beft-new-expert as a program: what it refuses (exit 2, the reason, nothing
// written), what it writes and the steps it prints.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/system/run_support.hpp"

namespace {

namespace fs = std::filesystem;
using beft::system_test::binDir;
using beft::system_test::makeTempDir;
using beft::system_test::ProgramResult;
using beft::system_test::runCommand;

class NewExpertProgram : public ::testing::Test {
 protected:
  void SetUp() override { root_ = makeTempDir("new_expert"); }
  void TearDown() override { fs::remove_all(root_); }

  ProgramResult generate(const std::string& arguments) const {
    return runCommand(binDir() + "/beft-new-expert " + arguments + " --out " + root_ + " 2>&1", 60);
  }
  std::vector<std::string> filesUnderRoot() const {
    std::vector<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(root_))
      if (entry.is_regular_file()) files.push_back(fs::relative(entry.path(), root_).string());
    return files;
  }
  void expectRefused(const std::string& arguments, const std::string& reason) const {
    const ProgramResult run = generate(arguments);
    EXPECT_EQ(run.exit_code, 2) << arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(reason), std::string::npos) << arguments << "\n" << run.output;
    EXPECT_EQ(filesUnderRoot(), std::vector<std::string>{}) << arguments;
  }

  std::string root_;
};

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST_F(NewExpertProgram, RefusesANameThatIsNotALowercaseIdentifier) {
  for (const char* name : {"Threat", "9lives", "threat-map", "threat__map", "threat_", "'a b'"})
    expectRefused(std::string(name) + " --writes TASK_COMMAND", "is not a lowercase identifier");
  expectRefused("class --writes TASK_COMMAND", "is a C++ keyword or a name in use");
}

TEST_F(NewExpertProgram, RefusesANameThatExists) {
  expectRefused("dw --writes TASK_COMMAND", "an expert named 'dw' already exists: modules/experts/dw");
  expectRefused("run --writes TASK_COMMAND", "a program beft-run already exists");
  fs::create_directories(fs::path(root_) / "tests/experts/threat");
  expectRefused("threat --writes TASK_COMMAND", "an expert named 'threat' already exists: tests/experts/threat");
}

TEST_F(NewExpertProgram, RefusesAChannelNotInTheTable) {
  expectRefused("threat --reads ROBOT_STATE NO_SUCH --writes TASK_COMMAND",
                "--reads NO_SUCH: no such channel in BEFT_CHANNELS");
  expectRefused("threat --writes THREATS", "--writes THREATS: no such channel in BEFT_CHANNELS");
  expectRefused("threat --reads ROBOT_STATE", "no --writes CHANNEL");
  expectRefused("threat --new-channel GEOMETRY:geometry2_t", "--new-channel GEOMETRY: already in the channel table");
  expectRefused("threat --reads TASK_COMMAND --writes GEOMETRY", "task_command_t has no utime and tick");
}

TEST_F(NewExpertProgram, WritesTheExpertAndItsTestsAndPrintsEveryNet) {
  const ProgramResult run = generate("threat --reads ROBOT_STATE --writes TASK_COMMAND --new-channel THREATS:threats_t");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* file : {"modules/experts/threat/CMakeLists.txt", "modules/experts/threat/main.cpp",
                           "modules/experts/threat/threat_expert.hpp", "modules/experts/threat/threat_expert.cpp",
                           "tests/experts/threat/CMakeLists.txt", "tests/experts/threat/test_threat_expert.cpp",
                           "lcmtypes/threats_t.lcm"}) {
    EXPECT_TRUE(fs::is_regular_file(fs::path(root_) / file)) << file;
    EXPECT_NE(run.output.find(std::string("  ") + file + "\n"), std::string::npos) << file;
  }
  EXPECT_EQ(filesUnderRoot().size(), 7u);
  const std::string header = readFile(fs::path(root_) / "modules/experts/threat/threat_expert.hpp");
  EXPECT_NE(header.find("expert::TickInput<robot_state_t> robot_state_{*this, channels::kRobotState};"),
            std::string::npos) << header;
  EXPECT_NE(header.find("expert::OutputPort<threats_t> threats_out_{*this, channels::kThreats};"), std::string::npos);
  // The libraries tests/tools/new_expert/CMakeLists.txt builds the generated sample with.
  EXPECT_NE(readFile(fs::path(root_) / "modules/experts/threat/CMakeLists.txt")
                .find("target_link_libraries(beft_expert_threat PUBLIC beft_expert beft_common beft_lcmtypes)"),
            std::string::npos);
  for (const auto& net : fs::directory_iterator(fs::path(BEFT_SOURCE_DIR) / "scenarios/nets"))
    EXPECT_NE(run.output.find("scenarios/nets/" + net.path().filename().string() + ": after "), std::string::npos)
        << net.path().filename();
  EXPECT_NE(run.output.find("<process name=\"threat\" host=\"${expert_host}\" command=\"beft-threat\" group=\"high\""),
            std::string::npos) << run.output;
  // The channel's table line is written as DYNAMIC_WEIGHTS' (the columns after the type kept).
  const std::string table = readFile(fs::path(BEFT_SOURCE_DIR) / "modules/lib/common/channels.hpp");
  const std::size_t reference = table.find("\"DYNAMIC_WEIGHTS\", dynamic_weights_t");
  ASSERT_NE(reference, std::string::npos);
  const std::size_t columns = reference + std::string("\"DYNAMIC_WEIGHTS\", dynamic_weights_t").size();
  const std::string rest = table.substr(columns, table.find(')', columns) - columns);
  EXPECT_NE(run.output.find("  X(kThreats, \"THREATS\", threats_t" + rest + ")"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("build/bin/beft-threat --interface"), std::string::npos);
}

TEST_F(NewExpertProgram, ASecondRunOfTheSameNameIsRefusedAndChangesNothing) {
  ASSERT_EQ(generate("threat --writes TASK_COMMAND").exit_code, 0);
  const auto files = filesUnderRoot();
  const std::string source = readFile(fs::path(root_) / "modules/experts/threat/threat_expert.cpp");
  const ProgramResult again = generate("threat --reads ROBOT_STATE --writes GEOMETRY");
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.output.find("an expert named 'threat' already exists"), std::string::npos) << again.output;
  EXPECT_EQ(filesUnderRoot(), files);
  EXPECT_EQ(readFile(fs::path(root_) / "modules/experts/threat/threat_expert.cpp"), source);
}

// A run killed while moving its staged files into place (some moved, the
// staging folder marked complete): the next run moves the rest and prints
// what the killed run would have printed.
TEST_F(NewExpertProgram, ARunKilledWhileMovingItsFilesIsFinishedByTheNextRun) {
  const ProgramResult first = generate("threat --writes TASK_COMMAND");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const auto files = filesUnderRoot();
  const std::string source = readFile(fs::path(root_) / "modules/experts/threat/threat_expert.cpp");
  const fs::path staging = fs::path(root_) / ".beft-new-expert-staging";
  for (const char* moved_back : {"modules/experts/threat/threat_expert.cpp", "tests/experts/threat/CMakeLists.txt"}) {
    fs::create_directories((staging / moved_back).parent_path());
    fs::rename(fs::path(root_) / moved_back, staging / moved_back);
  }
  std::ofstream(staging / ".steps") << "the steps of the killed run\n";
  std::ofstream(staging / ".complete");
  const ProgramResult next = generate("other --writes TASK_COMMAND");
  EXPECT_EQ(next.exit_code, 0) << next.output;
  EXPECT_NE(next.output.find("the steps of the killed run"), std::string::npos) << next.output;
  EXPECT_FALSE(fs::exists(staging));
  EXPECT_EQ(filesUnderRoot(), files) << "'other' is not written: the interrupted run is finished first";
  EXPECT_EQ(readFile(fs::path(root_) / "modules/experts/threat/threat_expert.cpp"), source);
}

// A run killed while writing (the staging folder not marked complete) put
// nothing in place: the next run drops what it staged and writes its own.
TEST_F(NewExpertProgram, ARunKilledWhileWritingLeavesNothingBehind) {
  const fs::path staging = fs::path(root_) / ".beft-new-expert-staging";
  fs::create_directories(staging / "modules/experts/threat");
  std::ofstream(staging / "modules/experts/threat/main.cpp") << "// cut short";
  const ProgramResult run = generate("threat --writes TASK_COMMAND");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_FALSE(fs::exists(staging));
  EXPECT_NE(readFile(fs::path(root_) / "modules/experts/threat/main.cpp").find("int main"), std::string::npos);
}

TEST(NewExpertHelp, ExplainsTheCommand) {
  const ProgramResult run = runCommand(binDir() + "/beft-new-expert --help 2>&1", 60);
  EXPECT_EQ(run.exit_code, 0);
  for (const char* words : {"--reads", "--writes", "--new-channel", "--level", "--after", "--out", "exit code 2"})
    EXPECT_NE(run.output.find(words), std::string::npos) << words;
}

}  // namespace

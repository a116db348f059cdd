// beft-key new: a new random key, readable by its owner only, never over an existing file.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "lib/transport/message_key.hpp"

namespace {

struct Result {
  int exit_code = -1;
  std::string output;
};

Result runKey(const std::string& arguments) {
  Result result;
  FILE* pipe = popen((std::string(BEFT_KEY_BINARY) + " " + arguments + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) result.output += buffer;
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

class KeyTool : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (std::filesystem::temp_directory_path() / "beft_key_tool_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }
  std::string dir_;
};

}  // namespace

TEST_F(KeyTool, WritesARandomHexKeyReadableByItsOwnerOnly) {
  const std::string first = dir_ + "/first.key", second = dir_ + "/second.key";
  const mode_t old_mask = umask(0);  // a permissive umask must not widen the mode
  const Result made = runKey("new " + first);
  umask(old_mask);
  ASSERT_EQ(made.exit_code, 0) << made.output;
  EXPECT_NE(made.output.find(first), std::string::npos) << made.output;
  ASSERT_EQ(runKey("new " + second).exit_code, 0);
  struct stat info {};
  ASSERT_EQ(stat(first.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0600u);
  const std::string text = readAll(first);
  ASSERT_EQ(text.size(), 65u) << text;  // 64 hexadecimal digits and a newline
  EXPECT_EQ(text.find_first_not_of("0123456789abcdef"), 64u);
  EXPECT_NE(text, readAll(second));
  std::string why;
  EXPECT_TRUE(beft::transport::MessageKey::fromFile(first, &why)) << why;
}

TEST_F(KeyTool, NeverReplacesAnExistingFile) {
  const std::string path = dir_ + "/run.key";
  std::ofstream(path) << "the key of another run\n";
  const Result refused = runKey("new " + path);
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_NE(refused.output.find("exists"), std::string::npos) << refused.output;
  EXPECT_EQ(readAll(path), "the key of another run\n");
}

TEST_F(KeyTool, SaysWhatItDoesAndNeedsASubcommand) {
  const Result help = runKey("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("new"), std::string::npos) << help.output;
  EXPECT_NE(runKey("").exit_code, 0);
  EXPECT_NE(runKey("new " + dir_ + "/no_such_folder/run.key").exit_code, 0);
}

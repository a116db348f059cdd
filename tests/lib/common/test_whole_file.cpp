// Files written whole or not at all.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lib/common/whole_file.hpp"

namespace {

namespace fs = std::filesystem;

std::string contentOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(WholeFile, ReplacesTheFileAndLeavesNoPartialBehind) {
  char pattern[] = "/tmp/beft_whole_file_XXXXXX";
  ASSERT_NE(mkdtemp(pattern), nullptr);
  const fs::path dir = pattern;
  const std::string target = (dir / "net.svg").string();
  beft::writeWholeFile(target, "first");
  beft::writeWholeFile(target, "second, longer");
  EXPECT_EQ(contentOf(target), "second, longer");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  // The partial file keeps the folder and the extension (tools pick a format by it).
  const fs::path partial = beft::partialPathFor(target);
  EXPECT_EQ(partial.parent_path(), dir);
  EXPECT_EQ(partial.extension(), ".svg");
  EXPECT_NE(partial.filename().string().find(".net.partial-"), std::string::npos);
  // Nowhere to write: an error naming the file, nothing left behind.
  try {
    beft::writeWholeFile((dir / "no" / "such.txt").string(), "x");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("such.txt"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace

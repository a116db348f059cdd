#include "tests/system/run_folders.hpp"

#include <stdlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace beft::system_test {
namespace {

struct MadeFolders {
  std::mutex mutex;
  std::vector<std::string> paths;
};

MadeFolders& madeFolders() {
  static MadeFolders folders;
  return folders;
}

bool keepAlways() {
  const char* keep = std::getenv("BEFT_KEEP_TEST_DIRS");
  return keep != nullptr && *keep != '\0' && std::strcmp(keep, "0") != 0;
}

// At the end of the test program: the folders go when every test passed
// (a full ctest would otherwise leave gigabytes of run logs in /tmp).
class RemoveFoldersIfPassed : public ::testing::EmptyTestEventListener {
  void OnTestProgramEnd(const ::testing::UnitTest& unit_test) override {
    MadeFolders& folders = madeFolders();
    const std::lock_guard<std::mutex> lock(folders.mutex);
    if (!unit_test.Passed() || keepAlways()) {
      for (const auto& path : folders.paths) std::fprintf(stderr, "[test] run folder kept: %s\n", path.c_str());
      return;
    }
    for (const auto& path : folders.paths) {
      std::error_code error;
      std::filesystem::remove_all(path, error);
      if (error) std::fprintf(stderr, "[test] cannot remove %s: %s\n", path.c_str(), error.message().c_str());
    }
  }
};

}  // namespace

std::string makeTempDir(const std::string& tag) {
  std::string pattern = "/tmp/beft_" + tag + "_XXXXXX";
  if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp " + pattern + ": " + std::strerror(errno));
  MadeFolders& folders = madeFolders();
  const std::lock_guard<std::mutex> lock(folders.mutex);
  if (folders.paths.empty()) ::testing::UnitTest::GetInstance()->listeners().Append(new RemoveFoldersIfPassed);
  folders.paths.push_back(pattern);
  return pattern;
}

}  // namespace beft::system_test

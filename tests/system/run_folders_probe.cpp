// run_folders_probe: one test that makes a run folder, writes its path on
// stdout and fails when PROBE_FAIL is set; test_run_folders runs it to see
// what becomes of the folder.
#include <cstdio>
#include <cstdlib>

#include <gtest/gtest.h>

#include "tests/system/run_folders.hpp"

TEST(RunFoldersProbe, MakesAFolder) {
  const std::string dir = beft::system_test::makeTempDir("probe");
  std::printf("made %s\n", dir.c_str());
  if (std::getenv("PROBE_FAIL") != nullptr) ADD_FAILURE() << "failing as asked";
}

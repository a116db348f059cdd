// The main of the system test programs that run as one ctest test each:
// GoogleTest's, except that a program whose every test was skipped (a
// machine without what it needs) exits with kSkipped, which ctest shows as
// skipped (SKIP_RETURN_CODE in CMakeLists.txt), not as passed.
#include <gtest/gtest.h>

#include <cstdio>

namespace {
constexpr int kSkipped = 77;
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  const int failed = RUN_ALL_TESTS();
  if (failed != 0) return failed;
  const testing::UnitTest& unit = *testing::UnitTest::GetInstance();
  if (unit.test_to_run_count() > 0 && unit.skipped_test_count() == unit.test_to_run_count()) {
    std::printf("[skipped] every test of this program was skipped: the reason is printed above\n");
    return kSkipped;
  }
  return 0;
}

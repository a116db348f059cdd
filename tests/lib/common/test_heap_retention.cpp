// Freed memory kept for the next allocation: a buffer built every firing
// faults its pages in once, not every time.
#include <malloc.h>
#include <sys/resource.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "lib/common/heap_retention.hpp"

namespace {

long minorFaults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// What a firing of exploration does: two map-sized buffers (a distance field
// and its working copy, 480 kB each), filled, used, freed. Returns the page
// faults of `rounds` such firings after a first one.
long faultsOfRepeatedFirings(int rounds) {
  constexpr std::size_t kCells = 60000;  // a 300 x 200 obstacle map
  auto firing = [] {
    std::vector<double> field(kCells, 1.0), work(kCells, 2.0);
    volatile double sink = field[kCells / 2] + work[kCells / 3];
    (void)sink;
  };
  firing();
  const long before = minorFaults();
  for (int i = 0; i < rounds; ++i) firing();
  return minorFaults() - before;
}

constexpr int kRounds = 20;
constexpr long kPagesPerFiring = 2 * 60000 * sizeof(double) / 4096;  // 234

TEST(HeapRetention, ABufferBuiltEveryFiringFaultsItsPagesInOnlyOnce) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer brings an allocator of its own";
#endif
  unsetenv("BEFT_RETAIN_HEAP");
  // glibc with its thresholds at their starting values (and not adjusted on
  // the fly): each firing maps fresh pages and faults them all in.
  ASSERT_EQ(mallopt(M_MMAP_THRESHOLD, 128 * 1024), 1);
  ASSERT_EQ(mallopt(M_TRIM_THRESHOLD, 128 * 1024), 1);
  const long returned = faultsOfRepeatedFirings(kRounds);
  EXPECT_GT(returned, kRounds * kPagesPerFiring / 2) << "the comparison shows nothing on this C library";

  ASSERT_TRUE(beft::retainFreedHeapMemory());
  faultsOfRepeatedFirings(1);  // the heap grows to the firing's size once
  const long retained = faultsOfRepeatedFirings(kRounds);
  EXPECT_LT(retained, kPagesPerFiring) << "faults in " << kRounds << " firings with the heap retained";
}

TEST(HeapRetention, TheEnvironmentCanKeepTheDefaults) {
  setenv("BEFT_RETAIN_HEAP", "0", 1);
  EXPECT_FALSE(beft::retainFreedHeapMemory());
  unsetenv("BEFT_RETAIN_HEAP");
}

}  // namespace

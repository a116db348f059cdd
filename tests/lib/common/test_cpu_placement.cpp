// A helper thread is kept off the CPU of the thread it works beside.
#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "lib/common/cpu_placement.hpp"

namespace {

std::vector<int> cpusOf(const cpu_set_t& set) {
  std::vector<int> cpus;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
    if (CPU_ISSET(cpu, &set)) cpus.push_back(cpu);
  return cpus;
}

void pinCallerTo(int cpu) {
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(cpu, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
}

cpu_set_t affinityOf(pthread_t thread) {
  cpu_set_t set;
  CPU_ZERO(&set);
  EXPECT_EQ(pthread_getaffinity_np(thread, sizeof set, &set), 0);
  return set;
}

TEST(HelperPlacement, TheHelperMayRunAnywhereButOnTheCallersCpu) {
  cpu_set_t allowed;
  ASSERT_EQ(sched_getaffinity(0, sizeof allowed, &allowed), 0);
  const std::vector<int> cpus = cpusOf(allowed);
  beft::HelperPlacement placement;  // remembers `allowed`
  std::atomic<bool> release{false};
  std::thread helper([&] {
    while (!release) std::this_thread::yield();
  });

  for (int caller_cpu : cpus) {
    pinCallerTo(caller_cpu);
    placement.keepOffMyCpu(helper.native_handle());
    cpu_set_t expected = allowed;
    if (cpus.size() > 1) CPU_CLR(caller_cpu, &expected);  // one CPU: left as it was
    const cpu_set_t got = affinityOf(helper.native_handle());
    EXPECT_EQ(cpusOf(got), cpusOf(expected)) << "caller on CPU " << caller_cpu;
  }
  release = true;
  helper.join();
  ASSERT_EQ(sched_setaffinity(0, sizeof allowed, &allowed), 0);
}

}  // namespace

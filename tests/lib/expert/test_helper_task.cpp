// The helper thread an expert may run one part of a firing on.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "lib/expert/helper_task.hpp"

using beft::expert::HelperTask;
using beft::expert::WaitOnExit;

TEST(HelperTask, RunsEachJobOnItsThreadBeforeWaitReturns) {
  HelperTask task;
  const std::thread::id caller = std::this_thread::get_id();
  for (int round = 0; round < 50; ++round) {
    int result = 0;
    std::thread::id ran_on;
    task.start([&] {
      ran_on = std::this_thread::get_id();
      for (int i = 1; i <= 1000; ++i) result += i;
    });
    task.wait();
    EXPECT_EQ(result, 500500) << "round " << round;
    EXPECT_NE(ran_on, caller);
  }
  task.wait();  // nothing running: returns at once
}

TEST(HelperTask, WaitRethrowsTheJobsExceptionOnceAndTheTaskGoesOn) {
  HelperTask task;
  task.start([] { throw std::runtime_error("depth frame has no pixels"); });
  try {
    task.wait();
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "depth frame has no pixels");
  }
  EXPECT_NO_THROW(task.wait());
  bool ran = false;
  task.start([&] { ran = true; });
  task.wait();
  EXPECT_TRUE(ran);
}

TEST(HelperTask, RefusesASecondJobBeforeTheFirstIsWaitedFor) {
  HelperTask task;
  std::atomic<bool> release{false};
  task.start([&] {
    while (!release) std::this_thread::yield();
  });
  EXPECT_THROW(task.start([] {}), std::logic_error);
  release = true;
  task.wait();
}

TEST(HelperTask, WaitOnExitWaitsWhenTheCallerThrows) {
  HelperTask task;
  std::atomic<bool> finished{false};
  try {
    task.start([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      finished = true;
    });
    WaitOnExit guard(task);
    throw std::runtime_error("percepts failed");
  } catch (const std::runtime_error&) {
    EXPECT_TRUE(finished) << "left the scope while the job still ran";
  }
}

TEST(HelperTask, DestructorWaitsForARunningJob) {
  std::atomic<bool> finished{false};
  {
    HelperTask task;
    task.start([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      finished = true;
    });
  }
  EXPECT_TRUE(finished);
}

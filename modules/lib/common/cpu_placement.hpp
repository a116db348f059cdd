// Keeps a helper thread off the CPU of the thread it works beside.
//
// Why: Linux wakes a thread on the CPU it last ran on or on its waker's, and
// looks for an idle CPU only among those that share a cache with that one.
// Where the kernel is told of no shared cache (a virtual machine's CPUs, as
// on the 2-core machines this runs on), it looks no further: a helper woken
// by the thread it should run beside then waits for it on the same CPU, and
// the two run one after the other. Allowing the helper every CPU but the
// waker's current one puts it on another.
//
// The caller then waits for its helper with yieldUntil rather than by
// sleeping: waking a sleeping thread takes tens of microseconds on a virtual
// machine, a good part of a helper's job.
#pragma once

#include <pthread.h>
#include <sched.h>

#include <chrono>

namespace beft {

class HelperPlacement {
 public:
  // Remembers the CPUs the constructing thread may run on: the helper gets
  // those but one.
  HelperPlacement();

  // Call from the thread the helper works beside, before waking it. Costs a
  // system call only when that thread has moved to another CPU since the
  // last call. Does nothing when only one CPU is allowed.
  void keepOffMyCpu(pthread_t helper);

 private:
  cpu_set_t allowed_;
  int last_cpu_ = -1;
};

// Stays on the CPU until done() or `limit` passed, yielding to any other
// thread ready on it meanwhile. Returns done(). The caller then falls back
// to its sleeping wait.
template <typename Done>
bool yieldUntil(Done&& done, std::chrono::microseconds limit = std::chrono::milliseconds(2)) {
  const auto give_up = std::chrono::steady_clock::now() + limit;
  while (!done()) {
    if (std::chrono::steady_clock::now() >= give_up) return false;
    sched_yield();
  }
  return true;
}

}  // namespace beft

#include "lib/common/cpu_placement.hpp"

namespace beft {

HelperPlacement::HelperPlacement() {
  CPU_ZERO(&allowed_);
  if (sched_getaffinity(0, sizeof allowed_, &allowed_) != 0) CPU_ZERO(&allowed_);
}

void HelperPlacement::keepOffMyCpu(pthread_t helper) {
  const int cpu = sched_getcpu();
  if (cpu < 0 || cpu == last_cpu_ || !CPU_ISSET(cpu, &allowed_)) return;
  cpu_set_t others = allowed_;
  CPU_CLR(cpu, &others);
  if (CPU_COUNT(&others) == 0) return;  // one CPU: nowhere else to go
  if (pthread_setaffinity_np(helper, sizeof others, &others) == 0) last_cpu_ = cpu;
}

}  // namespace beft

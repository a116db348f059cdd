#include "lib/common/heap_retention.hpp"

#include <malloc.h>

#include <cstdlib>
#include <cstring>

namespace beft {

bool retainFreedHeapMemory() {
  const char* setting = std::getenv("BEFT_RETAIN_HEAP");
  if (setting != nullptr && std::strcmp(setting, "0") == 0) return false;
  // Blocks up to 32 MiB (glibc's largest mmap threshold) come from the heap;
  // the heap's top is given back only beyond 256 MiB free; it grows 16 MiB
  // at a time (address space only: pages are touched when used).
  bool ok = mallopt(M_MMAP_THRESHOLD, 32 << 20) == 1;
  ok = mallopt(M_TRIM_THRESHOLD, 256 << 20) == 1 && ok;
  ok = mallopt(M_TOP_PAD, 16 << 20) == 1 && ok;
  return ok;
}

}  // namespace beft

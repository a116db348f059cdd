// Keeps the memory a process frees for its next allocations instead of
// handing it back to the kernel at once.
//
// Why: by default glibc gives the top of the heap back to the kernel whenever
// more than 128 kB of it is free, and serves large blocks (above an mmap
// threshold that starts at 128 kB) from fresh mappings it unmaps on free. A
// process that builds a large buffer every firing or request (a distance
// field of a 300 x 200 obstacle map is 480 kB of doubles) then takes a page
// fault for each 4 kB page of it every time, and a page fault costs
// microseconds, more on a virtual machine. Measured: the octile distance
// field of a 300 x 200 map, 3.4 ms -> 1.0 ms.
//
// The price: a process's resident memory stays at its peak instead of
// shrinking after it. BEFT_RETAIN_HEAP=0 in the environment keeps glibc's
// defaults (to measure the difference: ./beft bench mission).
#pragma once

namespace beft {

// Call once, first thing in main(). Returns false when BEFT_RETAIN_HEAP=0
// kept the defaults or the C library refused a setting.
bool retainFreedHeapMemory();

}  // namespace beft

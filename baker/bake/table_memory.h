// How a baking process keeps the memory of the tables it frees.
//
// A bake allocates and frees tables of tens of megabytes once per order
// (each order's density and radiance). glibc serves blocks above its mmap
// threshold (at most 32 MiB unless set) with fresh mappings and unmaps them
// when freed, so every order touched new pages again: about 75 000 page
// faults for the built-in Earth, 0.7 s of system time and 0.5 to 0.9 s of
// the 10 s whole process on 2 cores (docs/MEASUREMENTS.md). Raising the
// threshold and the trim threshold keeps freed tables in the heap for the
// next one, at the cost of a peak about 10 % higher (the heap is not
// returned between tables).
#pragma once

#include <cstddef>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace skybake {

// Blocks up to this size come from the heap and stay there when freed: above
// the largest table a default-sized bake allocates, so none is unmapped.
inline constexpr size_t kHeapTableBytes = size_t{1} << 30;

// For a process that bakes (the skybake command); no-op off glibc. Call
// before the first table is allocated.
inline void keepFreedTableMemory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kHeapTableBytes));
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(kHeapTableBytes));
#endif
}

}  // namespace skybake

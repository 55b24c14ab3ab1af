// What the bake process has used so far, for the bake report: CPU seconds
// over all threads and the peak resident memory.
#pragma once

#include <sys/resource.h>

namespace skybake {

// User plus system CPU seconds of the whole process, every thread.
inline double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// The peak resident set of the process, MiB.
inline double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux reports KiB
}

}  // namespace skybake

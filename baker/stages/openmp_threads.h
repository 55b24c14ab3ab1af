// The OpenMP thread count for one piece of work, restored when it ends.
// omp_set_num_threads changes the count for everything the calling thread
// starts afterwards: a library call that set it and left it would make a
// later call that asks for OpenMP's default run on the earlier count.
#pragma once

#include <omp.h>

#include <string>

#include "data_formats/error.h"

namespace skybake {

// More worker threads than this is a typo, not a machine: libgomp starts
// every one of them (10^5 threads crash it in GOMP_parallel, 10^9 exhaust
// its memory).
inline constexpr long long kMaxThreadCount = 4096;

// Throws Error(BadInput) "threads = <n>: ..." unless `threads` is 0 (all
// cores) or in [1, kMaxThreadCount]: the one check of every entry point's
// thread count (command line, Python module, library).
inline void requireThreadCount(long long threads) {
  if (threads < 0 || threads > kMaxThreadCount) {
    throw Error(ErrorKind::BadInput, "threads = " + std::to_string(threads) + ": must be 0 (all cores) or 1 to " +
                                         std::to_string(kMaxThreadCount));
  }
}

class ScopedOpenMpThreads {
 public:
  // threads > 0: that many; 0: leave OpenMP's current setting. Others are
  // refused (requireThreadCount).
  explicit ScopedOpenMpThreads(int threads) : previous_(omp_get_max_threads()) {
    requireThreadCount(threads);
    if (threads > 0) omp_set_num_threads(threads);
  }
  ~ScopedOpenMpThreads() { omp_set_num_threads(previous_); }
  ScopedOpenMpThreads(const ScopedOpenMpThreads&) = delete;
  ScopedOpenMpThreads& operator=(const ScopedOpenMpThreads&) = delete;

  // The count the work runs on.
  int threads() const { return omp_get_max_threads(); }

 private:
  int previous_;
};

}  // namespace skybake

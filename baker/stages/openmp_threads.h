// The OpenMP thread count for one piece of work, restored when it ends.
// omp_set_num_threads changes the count for everything the calling thread
// starts afterwards: a library call that set it and left it would make a
// later call that asks for OpenMP's default run on the earlier count.
#pragma once

#include <omp.h>

namespace skybake {

class ScopedOpenMpThreads {
 public:
  // threads > 0: that many; 0: leave OpenMP's current setting.
  explicit ScopedOpenMpThreads(int threads) : previous_(omp_get_max_threads()) {
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

// What the bake process has used so far, for the bake report: CPU seconds
// over all threads and the peak resident memory.
#pragma once

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

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

// Wall seconds since the kernel started the process, start-up (loading the
// shared libraries) included: what a user waits for. From /proc (Linux),
// to the kernel's clock tick (10 ms); -1 where /proc cannot be read.
inline double processWallSeconds() {
  std::ifstream stat_file("/proc/self/stat"), uptime_file("/proc/uptime");
  std::string stat;
  double uptime = 0.0;
  if (!std::getline(stat_file, stat) || !(uptime_file >> uptime)) return -1.0;
  // Field 22, start time in clock ticks after boot; the fields after the
  // command name, which may hold spaces, start after its closing ')'.
  std::istringstream fields(stat.substr(stat.rfind(')') + 2));
  std::string field;
  for (int i = 3; i <= 22 && fields >> field; ++i) {
  }
  const long ticks_per_second = sysconf(_SC_CLK_TCK);
  if (!fields || ticks_per_second <= 0) return -1.0;
  return uptime - std::stod(field) / static_cast<double>(ticks_per_second);
}

}  // namespace skybake

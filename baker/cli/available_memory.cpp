#include "baker/cli/available_memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "data_formats/error.h"

namespace skybake {
namespace {

// At or above this a limit is no limit: cgroups report none as "max" (v2) or
// as the largest page count (about 2^63 bytes, v1).
constexpr uint64_t kNoLimitFrom = uint64_t{1} << 60;

// The first number in a file, or nothing (absent file, "max").
std::optional<uint64_t> readNumber(const std::filesystem::path& file) {
  std::ifstream in(file);
  uint64_t value = 0;
  if (in >> value) return value;
  return std::nullopt;
}

// The number after `key` in a "key value" file (/proc/meminfo, memory.stat).
std::optional<uint64_t> readKeyed(const std::filesystem::path& file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string name;
    uint64_t value = 0;
    if (fields >> name >> value && (name == key || name == key + ":")) return value;
  }
  return std::nullopt;
}

// This process's size in bytes: field 0 of /proc/self/statm is the address
// space, field 5 data and stack (what RLIMIT_DATA counts).
uint64_t processBytes(size_t field) {
  std::ifstream in("/proc/self/statm");
  std::array<uint64_t, 7> pages{};
  for (uint64_t& p : pages) in >> p;
  return pages[field] * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
}

// What a resource limit leaves beyond the `used` bytes, if it is set.
std::optional<uint64_t> limitLeft(int resource, uint64_t used) {
  rlimit limit{};
  if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  return limit.rlim_cur > used ? limit.rlim_cur - used : 0;
}

// What the memory cgroup's limit leaves, with the file cache it would
// reclaim counted as free. Reads the cgroup mounted at /sys/fs/cgroup
// (v2) or /sys/fs/cgroup/memory (v1): the process's own in a container.
std::optional<uint64_t> cgroupLeft() {
  struct Layout {
    const char* limit;
    const char* usage;
    const char* stat;
    const char* inactive_file;
  };
  for (const Layout& l :
       {Layout{"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current", "/sys/fs/cgroup/memory.stat",
               "inactive_file"},
        Layout{"/sys/fs/cgroup/memory/memory.limit_in_bytes", "/sys/fs/cgroup/memory/memory.usage_in_bytes",
               "/sys/fs/cgroup/memory/memory.stat", "total_inactive_file"}}) {
    const std::optional<uint64_t> limit = readNumber(l.limit);
    const std::optional<uint64_t> usage = readNumber(l.usage);
    if (!limit || !usage || *limit >= kNoLimitFrom) continue;
    const uint64_t reclaimable = readKeyed(l.stat, l.inactive_file).value_or(0);
    const uint64_t used = *usage > reclaimable ? *usage - reclaimable : 0;
    return *limit > used ? *limit - used : 0;
  }
  return std::nullopt;
}

}  // namespace

std::string formatBytes(uint64_t bytes) {
  static constexpr const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double value = static_cast<double>(bytes);
  size_t unit = 0;
  while (value >= 1024.0 && unit + 1 < std::size(kUnits)) {
    value /= 1024.0;
    ++unit;
  }
  return unit == 0 ? fmt::format("{} B", bytes) : fmt::format("{:.1f} {}", value, kUnits[unit]);
}

AvailableMemory availableMemory() {
  AvailableMemory best;
  if (const std::optional<uint64_t> kib = readKeyed("/proc/meminfo", "MemAvailable")) {
    best.bytes = *kib * 1024;
  } else {
    best.bytes = static_cast<uint64_t>(::sysconf(_SC_AVPHYS_PAGES)) * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
  }
  best.description = fmt::format("this machine has {} available", formatBytes(best.bytes));
  auto consider = [&](std::optional<uint64_t> left, const char* source) {
    if (left && *left < best.bytes) {
      best.bytes = *left;
      best.description = fmt::format("this process may allocate {} more ({})", formatBytes(*left), source);
    }
  };
  consider(limitLeft(RLIMIT_AS, processBytes(0)), "address-space limit, ulimit -v");
  consider(limitLeft(RLIMIT_DATA, processBytes(5)), "data-size limit, ulimit -d");
  consider(cgroupLeft(), "memory cgroup limit");
  return best;
}

void requireMemoryAvailable(const std::string& what, uint64_t needed_bytes) {
  const AvailableMemory available = availableMemory();
  if (needed_bytes > available.bytes) {
    throwBadInput(fmt::format("{} needs about {}; {}", what, formatBytes(needed_bytes), available.description));
  }
}

}  // namespace skybake

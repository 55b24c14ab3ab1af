// How much memory this process can still allocate, and the refusal of work
// that needs more.
#pragma once

#include <cstdint>
#include <string>

namespace skybake {

struct AvailableMemory {
  uint64_t bytes = 0;
  // Where the figure comes from, ending a sentence: "this machine has 21.9
  // GiB available", "this process may allocate 3.6 GiB more (ulimit -v)".
  std::string description;
};

// The smallest of: the kernel's MemAvailable (what can be allocated without
// swapping), what the address-space and data-size limits (ulimit -v, -d)
// leave, and what the memory cgroup's limit leaves (reclaimable file cache
// counted as free).
AvailableMemory availableMemory();

// Throws Error(BadInput) "<what> needs about <bytes>; <where it comes from>"
// when `needed_bytes` exceeds availableMemory().
void requireMemoryAvailable(const std::string& what, uint64_t needed_bytes);

// "512 B", "1.5 KiB", "36.0 GiB", "2.3 TiB".
std::string formatBytes(uint64_t bytes);

}  // namespace skybake

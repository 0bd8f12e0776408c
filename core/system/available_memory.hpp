#pragma once
// How much memory this process may still use, and what says so: a run that would need more is
// refused before it starts (core/system/run_limits.hpp) instead of being killed by the kernel
// half-way (Linux overcommits: a large allocation rarely fails, the process is killed later).
#include <cstdint>
#include <string>

namespace fp {

struct MemoryBudget {
  std::uint64_t bytes = 0;  ///< what may still be allocated
  std::string source;       ///< which limit it is, for messages ("MemAvailable in /proc/meminfo", ...)
};

/// The smallest of: the kernel's estimate of memory available without swapping (MemAvailable in
/// /proc/meminfo), the address-space and data-segment limits (ulimit -v / RLIMIT_AS, RLIMIT_DATA)
/// less what the process already maps, and the memory cgroup's limit less its usage (v2
/// memory.max, v1 memory.limit_in_bytes). Where none can be read (not Linux), 2^63 bytes.
MemoryBudget available_memory();

}  // namespace fp

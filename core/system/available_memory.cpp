#include "core/system/available_memory.hpp"

#include <sys/resource.h>

#include <fstream>
#include <limits>
#include <sstream>

namespace fp {
namespace {

/// The value (in kB) of `key` in a /proc file of "Key:   123 kB" lines.
bool read_kb(const char* file, const std::string& key, std::uint64_t& kb) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, key.size() + 1, key + ":") == 0) {
      std::istringstream is(line.substr(key.size() + 1));
      return static_cast<bool>(is >> kb);
    }
  return false;
}

/// A file holding one number of bytes ("max" or a huge value means no limit).
bool read_bytes(const std::string& file, std::uint64_t& bytes) {
  std::ifstream in(file);
  std::string word;
  if (!(in >> word) || word == "max") return false;
  try {
    bytes = std::stoull(word);
  } catch (const std::exception&) {
    return false;
  }
  return bytes < (std::uint64_t{1} << 62);  // v1 writes 2^63 rounded down to a page for "none"
}

/// The unified (v2) cgroup of this process, from its "0::/path" line.
std::string cgroup_v2_folder() {
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, 3, "0::") == 0) return "/sys/fs/cgroup" + (line.size() > 4 ? line.substr(3) : std::string());
  return "/sys/fs/cgroup";
}

void consider(MemoryBudget& b, std::uint64_t bytes, const char* source) {
  if (bytes < b.bytes) b = {bytes, source};
}

void consider_rlimit(MemoryBudget& b, int resource, const char* status_key, const char* source) {
  rlimit lim{};
  if (getrlimit(resource, &lim) != 0 || lim.rlim_cur == RLIM_INFINITY) return;
  std::uint64_t used_kb = 0;
  read_kb("/proc/self/status", status_key, used_kb);
  const std::uint64_t used = used_kb * 1024;
  consider(b, lim.rlim_cur > used ? lim.rlim_cur - used : 0, source);
}

}  // namespace

MemoryBudget available_memory() {
  MemoryBudget b{std::uint64_t{1} << 63, "no limit found"};
  if (std::uint64_t kb = 0; read_kb("/proc/meminfo", "MemAvailable", kb)) consider(b, kb * 1024, "MemAvailable in /proc/meminfo");
  consider_rlimit(b, RLIMIT_AS, "VmSize", "the address-space limit (ulimit -v) less what the process maps");
  consider_rlimit(b, RLIMIT_DATA, "VmData", "the data-segment limit (ulimit -d) less what the process uses");
  const std::string v2 = cgroup_v2_folder();
  if (std::uint64_t max = 0, now = 0; read_bytes(v2 + "/memory.max", max)) {
    read_bytes(v2 + "/memory.current", now);
    consider(b, max > now ? max - now : 0, "the memory cgroup's memory.max less its memory.current");
  }
  if (std::uint64_t max = 0, now = 0; read_bytes("/sys/fs/cgroup/memory/memory.limit_in_bytes", max)) {
    read_bytes("/sys/fs/cgroup/memory/memory.usage_in_bytes", now);
    consider(b, max > now ? max - now : 0, "the memory cgroup's memory.limit_in_bytes less its usage");
  }
  return b;
}

}  // namespace fp

#pragma once
// Work cut into parts, run on a few threads: the analysis and the validation use it. What a
// part computes must not depend on the thread that runs it nor on the other parts, and the
// caller merges the parts' results in an order-free way (sums of integers, maxima, a sort by a
// total order), so a result never depends on the number of threads.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace fp {

/// Threads to use for `requested` (0: every hardware thread).
inline int thread_count(int requested) {
  if (requested > 0) return requested;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// Calls work(part) once for every part in [0, parts) on up to `threads` threads (the caller's
/// one of them), each thread taking the next part not yet taken, so the parts' order is the
/// order of their starts. The first exception thrown by a part is rethrown once all have
/// stopped (the parts not yet started are skipped).
template <class Work>
void for_each_part(std::size_t parts, int threads, Work&& work) {
  const std::size_t helpers = std::min<std::size_t>(parts, static_cast<std::size_t>(std::max(threads, 1))) - (parts > 0);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;
  auto run = [&] {
    for (std::size_t p; !failed.load(std::memory_order_relaxed) && (p = next.fetch_add(1)) < parts;) {
      try {
        work(p);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(helpers);
  for (std::size_t t = 0; t < helpers; ++t) pool.emplace_back(run);
  run();
  for (std::thread& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

/// [begin, end) of part `part` when `count` items are cut into `parts` nearly equal parts.
inline std::pair<std::size_t, std::size_t> part_range(std::size_t count, std::size_t part, std::size_t parts) {
  return {count * part / parts, count * (part + 1) / parts};
}

}  // namespace fp

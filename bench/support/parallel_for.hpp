#pragma once
// Independent tasks on all cores, for benchmarks whose measurements are not times (errors,
// energies): several runs at once would distort a clock, not a pixel error.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace c2f::bench {

/// Calls task(i) for every i < count on `threads` threads (0: all cores), each i once, in no
/// particular order. Rethrows the first exception a task threw, after every thread ended.
inline void parallel_for(std::size_t count, const std::function<void(std::size_t)>& task,
                         unsigned threads = 0) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors;
  std::mutex errors_mutex;
  const auto work = [&] {
    for (std::size_t i; (i = next++) < count;) {
      try {
        task(i);
      } catch (...) {
        const std::lock_guard lock(errors_mutex);
        errors.push_back(std::current_exception());
      }
    }
  };
  std::vector<std::thread> workers(threads - 1);
  for (std::thread& worker : workers) worker = std::thread(work);
  work();
  for (std::thread& worker : workers) worker.join();
  if (!errors.empty()) std::rethrow_exception(errors.front());
}

}  // namespace c2f::bench

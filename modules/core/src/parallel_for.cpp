#include "c2f/support/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace c2f {

unsigned resolved_threads(int requested) noexcept {
  if (requested >= 1) return static_cast<unsigned>(requested);
  return std::max(1U, std::thread::hardware_concurrency());
}

void parallel_for(std::size_t count, const std::function<void(std::size_t)>& task, int threads) {
  const std::size_t workers = std::min<std::size_t>(resolved_threads(threads), count);
  std::atomic<std::size_t> next{0};
  std::mutex failure_mutex;
  std::exception_ptr failure;
  std::size_t failed_index = count;
  const auto work = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < count;) {
      try {
        task(i);
      } catch (...) {
        const std::lock_guard lock(failure_mutex);
        if (i < failed_index) failed_index = i, failure = std::current_exception();
      }
    }
  };
  std::vector<std::jthread> helpers;  // none for one worker: all in order, here
  helpers.reserve(workers > 0 ? workers - 1 : 0);
  for (std::size_t t = 1; t < workers; ++t) helpers.emplace_back(work);
  work();
  helpers.clear();  // joins
  if (failure) std::rethrow_exception(failure);
}

void parallel_for_chunks(std::size_t count, std::size_t chunk,
                         const std::function<void(std::size_t, std::size_t, std::size_t)>& task,
                         int threads) {
  const std::size_t chunks = (count + chunk - 1) / chunk;
  const auto one = [&](std::size_t c) { task(c, c * chunk, std::min(count, (c + 1) * chunk)); };
  if (chunks <= 1 || resolved_threads(threads) == 1) {
    for (std::size_t c = 0; c < chunks; ++c) one(c);
    return;
  }
  parallel_for(chunks, one, threads);
}

}  // namespace c2f

// parallel_for runs every task once, on the threads asked for, and reports the failure of the
// lowest index whatever the threads' timing.

#include <catch2/catch.hpp>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "c2f/support/parallel_for.hpp"

using c2f::parallel_for;

TEST_CASE("parallel_for runs every index once on at most the threads asked for",
          "[core][threads]") {
  for (const int threads : {1, 2, 3, 8}) {
    std::vector<std::atomic<int>> runs(100);
    std::mutex ids_mutex;
    std::set<std::thread::id> ids;
    parallel_for(
        runs.size(),
        [&](std::size_t i) {
          ++runs[i];
          const std::lock_guard lock(ids_mutex);
          ids.insert(std::this_thread::get_id());
        },
        threads);
    INFO(threads << " threads");
    for (const auto& count : runs) CHECK(count == 1);
    CHECK(ids.size() <= static_cast<std::size_t>(threads));
  }
  std::vector<std::size_t> order;
  parallel_for(
      5, [&](std::size_t i) { order.push_back(i); }, 1);  // one thread: in order
  CHECK(order == std::vector<std::size_t>{0, 1, 2, 3, 4});
  parallel_for(
      0, [](std::size_t) { FAIL("no task to run"); }, 4);
  CHECK(c2f::resolved_threads(3) == 3);
  CHECK(c2f::resolved_threads(0) >= 1);
}

TEST_CASE("parallel_for rethrows the lowest failing index after every task ran",
          "[core][threads]") {
  for (const int threads : {1, 2, 4}) {
    std::atomic<int> ran{0};
    const auto task = [&](std::size_t i) {
      ++ran;
      if (i == 7 || i == 3 || i == 40) throw std::runtime_error("task " + std::to_string(i));
    };
    INFO(threads << " threads");
    CHECK_THROWS_WITH(parallel_for(50, task, threads), "task 3");
    CHECK(ran == 50);
  }
}

// parallel_for runs every task once, on the threads asked for, and reports the failure of the
// lowest index whatever the threads' timing.

#include <catch2/catch.hpp>

#include <atomic>
#include <barrier>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
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

TEST_CASE("parallel_for starts each thread on its own run of indices, the caller on the first",
          "[core][threads]") {
  // Every task waits at a barrier for one task of the other thread, so neither thread can take
  // an index of the other's run: thread w of 2 runs the w-th half, in order.
  for (int call = 0; call < 3; ++call) {  // the same split in every call
    std::barrier meet(2);
    std::vector<std::thread::id> ran_on(6);
    parallel_for(
        ran_on.size(),
        [&](std::size_t i) {
          ran_on[i] = std::this_thread::get_id();
          meet.arrive_and_wait();
        },
        2);
    INFO("call " << call);
    const std::thread::id caller = std::this_thread::get_id();
    CHECK(ran_on[0] == caller);
    CHECK(ran_on[1] == caller);
    CHECK(ran_on[2] == caller);
    CHECK(ran_on[3] != caller);
    CHECK(ran_on[4] == ran_on[3]);
    CHECK(ran_on[5] == ran_on[3]);
  }
  // A thread done with its run takes the rest of the other's: one slow task does not hold the
  // indices after it.
  std::atomic<int> after_slow{0};
  bool others_ran = false;
  parallel_for(
      8,
      [&](std::size_t i) {
        if (i == 4) {  // the helper's first: waits (10 s at most) for the other thread to run 5-7
          const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
          while (after_slow.load() < 3 && std::chrono::steady_clock::now() < give_up)
            std::this_thread::yield();
          others_ran = after_slow.load() == 3;
        } else if (i > 4) {
          ++after_slow;
        }
      },
      2);
  CHECK(others_ran);
}

TEST_CASE(
    "parallel_for and parallel_for_in_order rethrow the lowest failing index after every "
    "task ran",
    "[core][threads]") {
  std::vector<std::size_t> order(50);  // 49 .. 0: the lowest index fails last in the queue
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = order.size() - 1 - j;
  for (const int threads : {1, 2, 4}) {
    std::atomic<int> ran{0};
    const auto task = [&](std::size_t i) {
      ++ran;
      if (i == 7 || i == 3 || i == 40) throw std::runtime_error("task " + std::to_string(i));
    };
    INFO(threads << " threads");
    CHECK_THROWS_WITH(parallel_for(50, task, threads), "task 3");
    CHECK(ran == 50);
    ran = 0;
    CHECK_THROWS_WITH(c2f::parallel_for_in_order(order, task, threads), "task 3");
    CHECK(ran == 50);
  }
}

TEST_CASE("parallel_for_chunks covers every index once, in chunks fixed by the count",
          "[core][threads]") {
  for (const int threads : {1, 2, 3}) {
    std::vector<std::atomic<int>> visits(1000);
    std::vector<std::pair<std::size_t, std::size_t>> chunks(4);
    c2f::parallel_for_chunks(
        visits.size(), 256,
        [&](std::size_t c, std::size_t first, std::size_t last) {
          chunks[c] = {first, last};
          for (std::size_t i = first; i < last; ++i) ++visits[i];
        },
        threads);
    INFO(threads << " threads");
    for (const auto& count : visits) CHECK(count == 1);
    CHECK(chunks == std::vector<std::pair<std::size_t, std::size_t>>{
                        {0, 256}, {256, 512}, {512, 768}, {768, 1000}});
  }
  int calls = 0;
  c2f::parallel_for_chunks(
      0, 256, [&](std::size_t, std::size_t, std::size_t) { ++calls; }, 2);
  CHECK(calls == 0);
}

TEST_CASE("parallel_for from inside a task, and from several threads at once, runs every task",
          "[core][threads]") {
  // The helpers wait in a pool between calls; a call made while another owns it (nested, or
  // from another thread) must still run every task, on threads of its own.
  std::vector<std::atomic<int>> runs(8 * 50);
  parallel_for(
      8,
      [&](std::size_t outer) {
        parallel_for(
            50, [&](std::size_t inner) { ++runs[outer * 50 + inner]; }, 2);
      },
      2);
  for (const auto& count : runs) CHECK(count == 1);

  std::vector<std::atomic<int>> sums(4);
  {
    std::vector<std::jthread> callers;
    for (std::size_t c = 0; c < sums.size(); ++c) {
      callers.emplace_back([&, c] {
        for (int round = 0; round < 200; ++round)
          parallel_for(
              10, [&](std::size_t i) { sums[c] += static_cast<int>(i); }, 1 + round % 3);
      });
    }
  }
  for (const auto& sum : sums) CHECK(sum == 200 * 45);
}

TEST_CASE("parallel_for_in_order runs every task once, taking them from one queue in order",
          "[core][threads]") {
  const std::vector<std::size_t> order{3, 0, 4, 1, 2};
  for (const int threads : {1, 2, 3, 8}) {
    std::vector<std::atomic<int>> runs(order.size());
    c2f::parallel_for_in_order(
        order, [&](std::size_t i) { ++runs[i]; }, threads);
    INFO(threads << " threads");
    for (const auto& count : runs) CHECK(count == 1);
  }
  std::vector<std::size_t> ran;
  c2f::parallel_for_in_order(
      order, [&](std::size_t i) { ran.push_back(i); }, 1);  // one thread: in order
  CHECK(ran == order);
  c2f::parallel_for_in_order(
      {}, [](std::size_t) { FAIL("no task to run"); }, 2);

  // Two threads: while one runs the first task (which waits for the rest to be done), the
  // other takes every later task, in the queue's order.
  const std::vector<std::size_t> queue{5, 4, 3, 2, 1, 0};
  std::mutex ran_mutex;
  std::vector<std::size_t> others;
  std::atomic<int> done{0};
  bool long_task_waited = false;
  c2f::parallel_for_in_order(
      queue,
      [&](std::size_t i) {
        if (i == 5) {  // waits (10 s at most) for the other thread to run the other five
          const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
          while (done.load() < 5 && std::chrono::steady_clock::now() < give_up)
            std::this_thread::yield();
          long_task_waited = done.load() == 5;
          return;
        }
        const std::lock_guard lock(ran_mutex);
        others.push_back(i);
        ++done;
      },
      2);
  CHECK(long_task_waited);
  CHECK(others == std::vector<std::size_t>{4, 3, 2, 1, 0});
}

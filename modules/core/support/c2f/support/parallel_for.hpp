#pragma once
// Data preparation on several cores, with results that do not depend on how many: the work is
// split into tasks by index, each task writes only its own outputs, and nothing is reduced
// across tasks in an order that depends on scheduling. The thread count of each call is exactly
// the caller's (no global setting, unlike OpenCV's cv::setNumThreads). parallel_for's helper
// threads wait between calls in a process-wide pool, since the solve makes thousands of short
// calls per second (a call made while another owns the pool, e.g. from inside a task, starts
// threads of its own). Two shapes: parallel_for hands out independent tasks; run_team runs a
// team whose members work in lockstep (e.g. at a std::barrier), on threads started per call.

#include <cstddef>
#include <functional>
#include <latch>
#include <span>
#include <thread>
#include <vector>

namespace c2f {

/// The thread count `requested` stands for: itself when >= 1, else the machine's cores
/// (std::thread::hardware_concurrency, at least 1).
[[nodiscard]] unsigned resolved_threads(int requested) noexcept;

/// The bytes of a cache line on the machines c2f targets (x86-64, AArch64's common cores).
inline constexpr std::size_t kCacheLineBytes = 64;

/// A value on cache lines of its own. Tasks running at once that each write their own element
/// of an array (a max-flow part's search state, a part's list of touched nodes) would otherwise
/// write the same line when the elements are small, and each write would take the line from
/// the other core.
template <class T>
struct alignas(kCacheLineBytes) OnOwnLine {
  T value{};
};

/// Calls task(i) for every i < count, each once, on min(resolved_threads(threads), count)
/// threads (the calling thread among them; 1: all in the calling thread, in order). Thread w of
/// W starts on the w-th of W equal runs of indices, in order, and the calling thread is thread
/// 0, so calls over the same ranges of data find each range on the thread (and in the caches)
/// that last touched it; a thread done with its run takes what is left of the others'.
/// Rethrows the exception of the lowest index that threw, after every thread has ended (the
/// other tasks still run).
void parallel_for(std::size_t count, const std::function<void(std::size_t)>& task, int threads);

/// Calls task(order[j]) for every j < order.size(), each once, on up to
/// min(resolved_threads(threads), order.size()) threads (the calling thread among them; 1: all in
/// the calling thread, in `order`). The threads take the entries from one queue, in `order`, each
/// the next as soon as it is free: given the tasks longest first, the threads end close together
/// (list scheduling), where parallel_for's fixed runs could leave the long ones to one thread.
/// For tasks whose results do not depend on which thread runs them, so the order may come
/// from anything, timings included. Failures as parallel_for, the lowest task index first.
void parallel_for_in_order(std::span<const std::size_t> order,
                           const std::function<void(std::size_t)>& task, int threads);

/// Calls task(c, first, last) for every chunk c = [first, last) of [0, count), cut into chunks
/// of `chunk` indices (the last shorter; they depend on count and chunk only), each once, on
/// up to resolved_threads(threads) threads; with one chunk or one thread, in order on the
/// calling thread. Failures as parallel_for.
void parallel_for_chunks(std::size_t count, std::size_t chunk,
                         const std::function<void(std::size_t, std::size_t, std::size_t)>& task,
                         int threads);

/// Runs member(m) for every m < members, each on a thread of its own (the calling thread is
/// member 0), and returns when all have returned. Members may wait for each other (at a
/// std::barrier of `members`), so none starts before every thread exists: when a thread cannot
/// be started, none has begun, and the std::system_error is rethrown. A member must not throw.
template <typename Member>
void run_team(std::size_t members, const Member& member) {
  std::latch started(1);
  bool abandoned = false;             // written before `started` opens
  std::vector<std::jthread> helpers;  // joined when this returns or throws
  try {
    for (std::size_t m = 1; m < members; ++m) {
      helpers.emplace_back([&, m] {
        started.wait();
        if (!abandoned) member(m);
      });
    }
  } catch (...) {
    abandoned = true;
    started.count_down();
    throw;
  }
  started.count_down();
  member(0);
}

}  // namespace c2f

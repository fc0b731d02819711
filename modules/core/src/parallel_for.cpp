#include "c2f/support/parallel_for.hpp"

#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

namespace c2f {

namespace {

/// How long a thread of the pool polls for its next round (a helper) or for the helpers to end
/// theirs (the caller) before it sleeps on a futex. The solve's calls come microseconds apart,
/// with serial stretches of up to a few milliseconds between them (a max-flow's second stage, a
/// near move's set-up), and waking a sleeping thread costs more than polling through them, most
/// of all on a virtual machine, where a core with nothing to run halts and a wake-up is an
/// interrupt through the host. Adirondack's default c2f-stereo run on 2 threads, alternating:
/// the original level's solve 19.4 s against 20.2 s with 200 us (medians of 10 pairs; 2000 us
/// was the faster in all 10), 457 sleeps against 3988; grids in c2f.solve the same or faster.
constexpr std::chrono::microseconds kPollTime{2000};

/// Tells the core that this thread is polling (x86 PAUSE, Arm YIELD; elsewhere nothing).
inline void polling_pause() noexcept {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__) || defined(__arm__)
  asm volatile("yield");
#endif
}

/// Waits until `value` differs from `old` and returns what it holds then: polls for up to
/// kPollTime, then sleeps (std::atomic::wait).
template <class T>
T wait_for_change(const std::atomic<T>& value, T old) {
  const auto give_up = std::chrono::steady_clock::now() + kPollTime;
  for (unsigned polls = 1;; ++polls) {
    const T now = value.load(std::memory_order_acquire);
    if (now != old) return now;
    polling_pause();
    if (polls % 64 == 0) {
      if (std::chrono::steady_clock::now() >= give_up) break;
      std::this_thread::yield();  // a thread that wants this core (more threads than cores)
    }
  }
  for (T now; (now = value.load(std::memory_order_acquire)) == old;)
    value.wait(old, std::memory_order_acquire);
  return value.load(std::memory_order_acquire);
}

/// Threads kept waiting between parallel_for calls, so that a call costs a wake-up (a few
/// microseconds) instead of starting and joining threads (tens of microseconds each): the
/// solve's passes run thousands of short calls. One call owns the pool at a time; a call made
/// while it is owned (from inside a task, or from another thread) starts threads of its own,
/// as every call did before the pool. The pool is never destroyed (its threads wait until the
/// process ends), and a child process after fork() starts a new one.
class HelperPool {
 public:
  /// Runs work(0) on the calling thread and work(1) to work(helpers) on the pool's threads (the
  /// same helper for the same number in every call), and returns when all have returned; false,
  /// without running anything, when another call owns the pool. work() must not throw.
  bool try_run(std::size_t helpers, const std::function<void(std::size_t)>& work) {
    if (helpers >= kMaxHelpers) return false;
    bool idle = false;
    if (!busy_.compare_exchange_strong(idle, true, std::memory_order_acquire)) return false;
    struct Release {
      std::atomic<bool>& busy;
      ~Release() { busy.store(false, std::memory_order_release); }
    } release{busy_};
    while (threads_ < helpers) start_helper();  // throws std::system_error, nothing run yet
    work_ = &work;
    pending_.store(helpers, std::memory_order_relaxed);
    // The round's number and how many helpers it wants, in one word: a helper reads both at
    // once, so one that wakes late never reads another round's count.
    const std::uint64_t round = (state_.load(std::memory_order_relaxed) >> kCountBits) + 1;
    state_.store(round << kCountBits | helpers, std::memory_order_release);
    state_.notify_all();
    work(0);
    for (std::size_t left; (left = pending_.load(std::memory_order_acquire)) != 0;)
      wait_for_change(pending_, left);
    return true;
  }

 private:
  static constexpr int kCountBits = 16;
  static constexpr std::size_t kMaxHelpers = std::size_t{1} << kCountBits;

  /// Starts helper number threads_, which will take part in the rounds after the current one.
  void start_helper() {
    const std::size_t id = threads_;
    const std::uint64_t current = state_.load(std::memory_order_relaxed);
    std::thread([this, id, current] { serve(id, current); }).detach();
    ++threads_;
  }

  /// Helper `id`: in every round after `seen` that wants more than id helpers, runs the round's
  /// work.
  [[noreturn]] void serve(std::size_t id, std::uint64_t seen) {
    while (true) {
      seen = wait_for_change(state_, seen);
      if (id >= (seen & ((std::uint64_t{1} << kCountBits) - 1))) continue;
      (*work_)(id + 1);
      if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) pending_.notify_one();
    }
  }

  std::atomic<bool> busy_{false};  // owned by a call (a flag, not a mutex: tasks may call again)
  std::size_t threads_ = 0;        // helpers started; written by the owner
  const std::function<void(std::size_t)>* work_ = nullptr;
  std::atomic<std::uint64_t> state_{0};  // round << kCountBits | helpers wanted
  std::atomic<std::size_t> pending_{0};  // helpers of the round still working
};

std::atomic<HelperPool*> the_pool{nullptr};

/// The process's pool, made on first use.
HelperPool& helper_pool() {
  HelperPool* pool = the_pool.load(std::memory_order_acquire);
  if (pool != nullptr) return *pool;
  static const bool forks_handled = [] {
    // A child has none of the parent's threads: it leaves the parent's pool behind.
    pthread_atfork(nullptr, nullptr, [] { the_pool.store(nullptr); });
    return true;
  }();
  (void)forks_handled;
  auto* made = new HelperPool;
  if (the_pool.compare_exchange_strong(pool, made, std::memory_order_acq_rel)) return *made;
  delete made;  // another thread made it first
  return *pool;
}

/// Runs work(0) on the calling thread and work(1) to work(helpers) on as many more, and returns
/// when all have returned.
void run_with_helpers(std::size_t helpers, const std::function<void(std::size_t)>& work) {
  if (helpers == 0) {
    work(0);
    return;
  }
  if (helper_pool().try_run(helpers, work)) return;
  std::vector<std::jthread> started;  // joined when this returns
  started.reserve(helpers);
  for (std::size_t t = 1; t <= helpers; ++t) started.emplace_back(work, t);
  work(0);
}

/// The indices one worker of parallel_for owns, [next, end), taken from the front by it and,
/// once their own are done, by the others. A cache line each, so claims do not collide.
struct alignas(kCacheLineBytes) OwnedIndices {
  std::atomic<std::size_t> next;
  std::size_t end;
};

/// The failure of the lowest task index among the tasks of one call that threw, kept while the
/// others run (tasks on several threads record at once).
class LowestFailure {
 public:
  /// Keeps the exception being handled when `index` is below every index recorded so far.
  void record(std::size_t index) {
    const std::lock_guard lock(mutex_);
    if (!failure_ || index < index_) index_ = index, failure_ = std::current_exception();
  }
  /// Rethrows the kept exception, if any.
  void rethrow_if_any() const {
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr failure_;
  std::size_t index_ = 0;
};

}  // namespace

unsigned resolved_threads(int requested) noexcept {
  if (requested >= 1) return static_cast<unsigned>(requested);
  static const unsigned cores = std::max(1U, std::thread::hardware_concurrency());
  return cores;
}

void parallel_for(std::size_t count, const std::function<void(std::size_t)>& task, int threads) {
  const std::size_t workers = std::min<std::size_t>(resolved_threads(threads), count);
  LowestFailure failure;
  // Worker w owns the w-th of `workers` equal runs of indices: passes over the same ranges of
  // data (bands of variables, parts of a graph) then find it on the thread that touched it
  // last, in that core's caches. A worker done with its own takes what is left of the others'.
  std::vector<OwnedIndices> owned(std::max<std::size_t>(workers, 1));
  for (std::size_t w = 0; w < owned.size(); ++w) {
    owned[w].next.store(count * w / owned.size(), std::memory_order_relaxed);
    owned[w].end = count * (w + 1) / owned.size();
  }
  const std::function<void(std::size_t)> work = [&](std::size_t worker) {
    for (std::size_t k = 0; k < owned.size(); ++k) {
      OwnedIndices& run = owned[(worker + k) % owned.size()];
      for (std::size_t i; (i = run.next.fetch_add(1)) < run.end;) {
        try {
          task(i);
        } catch (...) {
          failure.record(i);
        }
      }
    }
  };
  run_with_helpers(workers > 0 ? workers - 1 : 0, work);  // none for one worker: in order, here
  failure.rethrow_if_any();
}

void parallel_for_in_order(std::span<const std::size_t> order,
                           const std::function<void(std::size_t)>& task, int threads) {
  const std::size_t workers = std::min<std::size_t>(resolved_threads(threads), order.size());
  LowestFailure failure;
  std::atomic<std::size_t> next{0};  // the queue's front
  const std::function<void(std::size_t)> work = [&](std::size_t) {
    for (std::size_t j; (j = next.fetch_add(1)) < order.size();) {
      try {
        task(order[j]);
      } catch (...) {
        failure.record(order[j]);
      }
    }
  };
  run_with_helpers(workers > 0 ? workers - 1 : 0, work);  // none for one worker: in order, here
  failure.rethrow_if_any();
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

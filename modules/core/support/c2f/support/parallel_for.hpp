#pragma once
// Data preparation on several cores, with results that do not depend on how many: the work is
// split into tasks by index, each task writes only its own outputs, and nothing is reduced
// across tasks in an order that depends on scheduling. Standard threads, started per call: the
// tasks are coarse (labels, rows), so a pool or work stealing would save nothing measurable,
// and the thread count of each call is exactly the caller's (no global setting, unlike OpenCV's
// cv::setNumThreads).

#include <cstddef>
#include <functional>

namespace c2f {

/// The thread count `requested` stands for: itself when >= 1, else the machine's cores
/// (std::thread::hardware_concurrency, at least 1).
[[nodiscard]] unsigned resolved_threads(int requested) noexcept;

/// Calls task(i) for every i < count, each once, on min(resolved_threads(threads), count)
/// threads (the calling thread among them; 1: all in the calling thread, in order). Tasks are
/// handed out in index order. Rethrows the exception of the lowest index that threw, after
/// every thread has ended (the other tasks still run).
void parallel_for(std::size_t count, const std::function<void(std::size_t)>& task, int threads);

}  // namespace c2f

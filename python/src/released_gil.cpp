#include "released_gil.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace c2f::python {

namespace py = pybind11;

namespace {

/// The regions without the GIL and whether the interpreter exits, under one mutex, which is
/// never held while waiting for the GIL.
struct Regions {
  std::mutex mutex;
  std::condition_variable ended;
  long open = 0;
  std::atomic<bool> exiting{false};
};

Regions& regions() {
  static Regions* shared = new Regions;  // never destroyed: threads may outlive static teardown
  return *shared;
}

void wait_for_regions() {
  Regions& r = regions();
  py::gil_scoped_release free;  // the regions need the GIL to end
  std::unique_lock lock(r.mutex);
  r.exiting = true;
  r.ended.wait(lock, [&] { return r.open == 0; });
}

}  // namespace

ReleasedGil::ReleasedGil() {
  Regions& r = regions();
  {
    const std::lock_guard lock(r.mutex);
    if (r.exiting) throw std::runtime_error("c2f: the interpreter is exiting; no new work starts");
    ++r.open;
  }
  state_ = PyEval_SaveThread();
}

ReleasedGil::~ReleasedGil() {
  Regions& r = regions();
  bool exiting = false;
  {
    const std::lock_guard lock(r.mutex);
    exiting = r.exiting;
    if (exiting) {
      --r.open;
      r.ended.notify_all();
    }
  }
  // Once the exit hook has run, this is a daemon thread (Python joins every other thread before
  // its exit hooks): it never takes the GIL back, since finalisation could end it inside a later
  // call and unwind our C++ frames. It waits, holding nothing, for the process to end.
  while (exiting) std::this_thread::sleep_for(std::chrono::hours(1));
  PyEval_RestoreThread(state_);
  const std::lock_guard lock(r.mutex);
  --r.open;
  r.ended.notify_all();
}

bool interpreter_exiting() noexcept {
  return regions().exiting;
}

void register_exit_hook() {
  py::module_::import("atexit").attr("register")(py::cpp_function(&wait_for_regions));
}

}  // namespace c2f::python

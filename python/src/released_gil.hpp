#pragma once
// The GIL released around the package's C++ work, safe when the interpreter exits.
//
// Once finalisation has begun, Python ends any thread that takes the GIL back by unwinding it
// from inside that call, and C++ frames cannot be unwound that way: the process aborts
// ("terminate called without an active exception"). A solve running in a daemon thread when the
// script ends, or when Ctrl-C ends the main thread while it joins a solving thread, would do
// exactly that. So the package registers an atexit hook, which Python runs before finalisation,
// that refuses every new release, asks running solves to stop at their next step
// (interpreter_exiting), and waits, without the GIL, until every released region has ended its
// work. A region that ends after the hook (a daemon thread's: Python joins every other thread
// before its exit hooks) never takes the GIL back but waits, holding nothing, for the process to
// end, so finalisation never stops a thread of ours inside C++ frames.

#include <pybind11/pybind11.h>

namespace c2f::python {

/// Releases the GIL for its lifetime; construct it with the GIL held. Throws RuntimeError when
/// the interpreter is exiting (no new work starts then).
class ReleasedGil {
 public:
  ReleasedGil();
  ~ReleasedGil();  ///< takes the GIL back and counts the region as ended (once the exit hook
                   ///< has run: counts it, then waits for the process to end)
  ReleasedGil(const ReleasedGil&) = delete;
  ReleasedGil& operator=(const ReleasedGil&) = delete;

 private:
  PyThreadState* state_;
};

/// Whether the interpreter has begun to exit: a running solve stops at its next step.
bool interpreter_exiting() noexcept;

/// Registers the atexit hook described above; called once, when the module is imported.
void register_exit_hook();

}  // namespace c2f::python

#pragma once
// The solver's progress reports (core/progress.hpp) seen from Python: forwarded to a callable
// and used as the points where a solve running without the GIL looks for Ctrl-C.
//
// Why here and not with a watchdog thread: Python runs its SIGINT handler (which raises
// KeyboardInterrupt) only on the main thread, the one that is inside the solve, so the check
// has to happen on the solve's own thread: the GIL is taken for a moment and
// PyErr_CheckSignals() runs the handler. stage() and note() come between steps of the pipeline
// and may throw; iteration() may run inside PETSc's C frames and must not, so an interrupt (or
// an exception of the callback) seen there is kept and thrown at the next stage() or note().
// Meshing, a CHOLMOD factorization and a PETSc Krylov solve therefore finish before a Ctrl-C
// takes effect.
#include <chrono>
#include <exception>
#include <string>

#include <pybind11/pybind11.h>

#include "core/progress.hpp"

namespace magfem::python {

class PyProgress : public Progress {
public:
  // callback: None (silent), True (the command line's lines on stderr) or a callable taking
  // (kind, text) with kind "stage", "note" or "iteration"; iteration reports are passed on at
  // most every `interval_s` seconds. Constructed with the GIL held; used without it.
  explicit PyProgress(pybind11::object callback, double interval_s = 0.5);
  ~PyProgress() override;

  void stage(const std::string& what) override;
  void note(const std::string& what) override;
  void iteration(const char* solver, int iteration, double relative_residual) override;

  // After the solve, with the GIL released: throws what iteration() kept, if anything.
  void rethrow_pending();

private:
  using Clock = std::chrono::steady_clock;
  // With the GIL held: runs Python's signal handlers, then the callback; throws
  // pybind11::error_already_set for KeyboardInterrupt or a callback's exception.
  void report(const char* kind, const std::string& text);

  pybind11::object callback_;
  bool print_ = false; // progress=True: the base class prints
  double interval_s_;
  Clock::time_point last_check_{}, last_call_{};
  std::exception_ptr pending_;
};

} // namespace magfem::python

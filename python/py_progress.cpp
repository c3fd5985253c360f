#include "python/py_progress.hpp"

#include <cstdio>

namespace py = pybind11;

namespace magfem::python {
namespace {
// How often iteration() takes the GIL to look for Ctrl-C: often enough to feel immediate,
// rarely enough to cost nothing next to a Krylov iteration.
constexpr double signal_check_interval_s = 0.05;

double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}
} // namespace

PyProgress::PyProgress(py::object callback, double interval_s)
    : Progress(stderr), interval_s_(interval_s) {
  if (py::isinstance<py::bool_>(callback))
    print_ = callback.cast<bool>();
  else if (!callback.is_none())
    callback_ = std::move(callback);
}

PyProgress::~PyProgress() = default;

void PyProgress::report(const char* kind, const std::string& text) {
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0)
    throw py::error_already_set();
  if (callback_)
    callback_(kind, text);
}

void PyProgress::stage(const std::string& what) {
  rethrow_pending();
  if (print_)
    Progress::stage(what);
  report("stage", what);
}

void PyProgress::note(const std::string& what) {
  rethrow_pending();
  if (print_)
    Progress::note(what);
  report("note", what);
}

void PyProgress::iteration(const char* solver, int iteration, double relative_residual) {
  if (print_)
    Progress::iteration(solver, iteration, relative_residual);
  if (pending_)
    return;
  const auto now = Clock::now();
  const bool call = callback_ && seconds(now - last_call_) >= interval_s_;
  if (!call && seconds(now - last_check_) < signal_check_interval_s)
    return;
  last_check_ = now;
  if (call)
    last_call_ = now;
  try {
    if (call) {
      char text[160];
      std::snprintf(text, sizeof text, "%s iteration %d, relative residual %.3e", solver, iteration,
                    relative_residual);
      report("iteration", text);
    } else {
      py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0)
        throw py::error_already_set();
    }
  } catch (...) { // kept: no exception may leave through a PETSc monitor
    pending_ = std::current_exception();
  }
}

void PyProgress::rethrow_pending() {
  if (pending_)
    std::rethrow_exception(std::exchange(pending_, nullptr));
}

} // namespace magfem::python

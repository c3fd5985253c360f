#pragma once
// Console progress of a long run: the stage being worked on (meshing, assembly, preconditioner
// set-up, solve, post-processing) and, at most every `interval_s` seconds, the Krylov
// iteration and its relative residual. A run without a Progress (a null pointer where one is
// taken) is silent: sweeps run many cases at once and have their own progress line.
//
// The three reports are virtual so that another front end can take them: the Python module
// forwards them to a callback and looks for Ctrl-C there (python/py_progress.hpp). stage()
// and note() are called between steps of the pipeline, where an exception thrown by an
// override unwinds cleanly; iteration() may be called from inside PETSc's C frames (its
// Krylov monitor), so an override must not throw from it.
#include <chrono>
#include <cstdio>
#include <string>

namespace magfem {

class Progress {
public:
  // `out`: where lines go (not owned; stderr keeps stdout for the results).
  explicit Progress(std::FILE* out = stderr, double interval_s = 2.0);
  virtual ~Progress() = default;
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  virtual void stage(const std::string& what);
  // Throttled by time: the first call after a stage only starts the clock, so a solve shorter
  // than the interval prints nothing but its stage.
  virtual void iteration(const char* solver, int iteration, double relative_residual);
  virtual void note(const std::string& what);

private:
  using Clock = std::chrono::steady_clock;
  std::FILE* out_;
  double interval_s_;
  Clock::time_point start_, stage_start_, last_print_;
  bool iterating_ = false;
};

} // namespace magfem

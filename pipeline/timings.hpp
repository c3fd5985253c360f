#pragma once
// Wall-clock seconds of a run's stages, as summary.json timings_s reports them.
#include <chrono>

namespace magfem {

struct Timings {
  double mesh = 0, assemble = 0, solve = 0, postprocess = 0, total = 0;
  double error_estimate = 0; // part of postprocess: recovery, indicator, force estimates
};

// Seconds since t0 on the steady clock the stages are timed with.
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace magfem

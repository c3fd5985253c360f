#pragma once
// Wall-clock seconds of a run's stages, as summary.json timings_s reports them.

namespace magfem {

struct Timings {
  double mesh = 0, assemble = 0, solve = 0, postprocess = 0, total = 0;
  double error_estimate = 0; // part of postprocess: recovery, indicator, force estimates
};

} // namespace magfem

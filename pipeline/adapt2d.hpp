#pragma once
// Adaptive refinement of a 2D planar or axisymmetric case, as spec.adapt asks (the loop,
// its marking and stopping rules: adapt_loop.hpp):
//   solve -> estimate the error per element (error_estimate2d.hpp) -> stop or a size field
//   from the indicators (adaptive_size2d.hpp) -> remesh with CGAL -> repeat.
#include <functional>
#include <memory>
#include <string>

#include "pipeline/adapt_loop.hpp"
#include "pipeline/run2d.hpp"

namespace magfem {

// The last pass's run, with run->adapt filled in. on_pass (may be empty) hears every pass as
// it ends. Throws as run_case_2d does.
std::unique_ptr<Run2D> run_adaptive_2d(const CaseSpec& spec, const RunOverrides& overrides,
                                       const std::function<void(const AdaptPass&)>& on_pass = {});

// The size of every element for the next pass (metres): its longest edge times
// adapt_size_ratios (adapt_loop.hpp); shell elements never grow (they keep the four layers the
// mesher gives the open boundary). Exposed for the tests.
std::vector<double> adapted_sizes(const Run2D& run, double target_pct, bool coarsen);

} // namespace magfem

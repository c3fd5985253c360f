#pragma once
// Adaptive refinement of a 2D planar or axisymmetric case, as spec.adapt asks:
//   solve -> estimate the error per element (error_estimate2d.hpp) -> stop when the estimated
//   energy error and the estimated error of every named quantity are below accuracy_pct ->
//   else a size field from the indicators (adaptive_size2d.hpp) -> remesh with CGAL -> repeat.
// The error of a named quantity (force, torque, probe) is its change between the last two
// passes, extrapolated with the observed ratio of successive changes; the energy's is the
// estimator's. Reaching max_passes or max_unknowns first returns the last pass with
// adapt.converged = false, a stop reason and a warning: never a silent pass.
#include <functional>
#include <memory>
#include <string>

#include "pipeline/run2d.hpp"

namespace magfem {

// The last pass's run, with run->adapt filled in. on_pass (may be empty) hears every pass as
// it ends. Throws as run_case_2d does.
std::unique_ptr<Run2D> run_adaptive_2d(const CaseSpec& spec, const RunOverrides& overrides,
                                       const std::function<void(const AdaptPass2D&)>& on_pass = {});

// One console line for a pass.
std::string describe_adapt_pass(const AdaptPass2D& pass);

// The size of every element for the next pass (metres), from the current indicators: elements
// whose indicator exceeds the equidistributed share of the target shrink, the others grow,
//   h_new = h * clamp((eta_target / eta_K)^(1/p), 0.3, 2)    (p: the element order),
// the rule of Zienkiewicz and Zhu (1987): eta_K scales like h^p in the energy norm when the
// number of elements is held fixed. Shell elements never grow (they keep the four layers the
// mesher gives the open boundary). target_pct: the energy error aimed at (energy_error_pct's
// measure). coarsen = false: no element grows (ratio <= 1). Exposed for the tests.
std::vector<double> adapted_sizes(const Run2D& run, double target_pct, bool coarsen);

} // namespace magfem

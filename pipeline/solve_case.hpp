#pragma once
// The solve a case asks for: adaptive refinement when it has an `adapt:` section (or
// `--accuracy` made one: adapt2d.hpp, adapt3d.hpp), else one solve on the case's mesh. Every
// caller that solves a whole case (solve, sweeps, actuator --verify, validate, Python) goes
// through here, so that no command drops a case's `adapt:` silently.
#include <functional>
#include <memory>

#include "pipeline/adapt_loop.hpp"
#include "pipeline/run2d.hpp"
#include "pipeline/run3d.hpp"

namespace magfem {

// on_pass (may be empty) hears every adaptive pass as it ends.
std::unique_ptr<Run2D> solve_case_2d(CaseSpec spec, const RunOverrides& overrides = {},
                                     const std::function<void(const AdaptPass&)>& on_pass = {});
std::unique_ptr<Run3D> solve_case_3d(CaseSpec spec, const RunOverrides& overrides = {},
                                     const std::function<void(const AdaptPass&)>& on_pass = {});

} // namespace magfem

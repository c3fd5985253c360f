#include "pipeline/solve_case.hpp"

#include "pipeline/adapt2d.hpp"
#include "pipeline/adapt3d.hpp"

namespace magfem {

std::unique_ptr<Run2D> solve_case_2d(CaseSpec spec, const RunOverrides& overrides,
                                     const std::function<void(const AdaptPass&)>& on_pass) {
  if (spec.adapt.enabled())
    return run_adaptive_2d(spec, overrides, on_pass);
  return run_case_2d(std::move(spec), overrides);
}

std::unique_ptr<Run3D> solve_case_3d(CaseSpec spec, const RunOverrides& overrides,
                                     const std::function<void(const AdaptPass&)>& on_pass) {
  if (spec.adapt.enabled())
    return run_adaptive_3d(spec, overrides, on_pass);
  return run_case_3d(std::move(spec), overrides);
}

} // namespace magfem

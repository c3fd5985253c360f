#pragma once
// Forces of a 3D run: the Maxwell stress tensor on spheres in air (case `forces:` entries of
// type sphere, and the sweep's separating sphere).
#include <vector>

#include <Eigen/Core>

#include "casefile/case_spec.hpp"
#include "pipeline/force_results.hpp"
#include "postproc/maxwell_stress.hpp"
#include "postproc/patch_recovery3d.hpp"

namespace magfem {

struct Run3D;

// Maxwell stress tensor on every `sphere` force of the case, from the air-only recovered B
// (postproc/maxwell_stress3d.hpp); a sphere that crosses matter is an InputError.
std::vector<ForceResult> compute_forces_3d(const Run3D& run);

// Error estimates of the stress-tensor forces (sphere and box) in `forces` (as
// compute_forces_3d made them, in that order): per component, the spread of the reported
// value and the same surface integral of the element B and of the patch-recovered B*
// (postproc/force_estimate3d.hpp); why, in force3d.cpp. Lorentz forces are left unestimated.
void estimate_force_errors_3d(const Run3D& run, const PatchRecovery3D& recovery,
                              std::vector<ForceResult>& forces);

// The quadrature points of a sphere or box force's surface, as the reported result and its
// estimate sample it (empty for other kinds).
std::vector<SurfacePoint> force_surface_points(const ForceSpec& f);

// The case with a stress sphere about the origin added to its forces (named `name`), so that
// the mesh is refined on it like on a sphere probe.
CaseSpec with_stress_sphere(CaseSpec spec, double radius, const std::string& name);

} // namespace magfem

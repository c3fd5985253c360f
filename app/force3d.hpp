#pragma once
// Forces of a 3D run: the Maxwell stress tensor on spheres in air (case `forces:` entries of
// type sphere, and the sweep's separating sphere).
#include <vector>

#include <Eigen/Core>

#include "app/force_results.hpp"
#include "casefile/case_spec.hpp"

namespace magfem {

struct Run3D;

// Force on everything inside the sphere and torque about torque_point, from the recovered
// (nodal, P2-interpolated) B: it is continuous, so the quadrature does not see the element
// jumps of the raw B.
ForceResult stress_on_sphere_3d(const Run3D& run, const Eigen::Vector3d& center, double radius,
                                const Eigen::Vector3d& torque_point);

std::vector<ForceResult> compute_forces_3d(const Run3D& run);

// The case with a stress sphere about the origin added to its forces (named `name`), so that
// the mesh is refined on it like on a sphere probe.
CaseSpec with_stress_sphere(CaseSpec spec, double radius, const std::string& name);

// The part of a force spec's relative spread: max component difference / max magnitude.
double relative_difference(const ForceResult& a, const ForceResult& b);

} // namespace magfem

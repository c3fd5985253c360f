#pragma once
// The local field error around a 3D probe's points, from the energy-norm indicators of the
// error estimate (error_estimate3d.hpp): what goal-oriented refinement (pipeline/adapt3d.cpp)
// sizes the tets near a named probe table with, and the estimate it reports for that table.
//
// Why from eta_K and not from B* - B_h at the points themselves: the element field's error
// oscillates inside a tet (it vanishes at some points of every element), so the difference at
// one point can read near zero where the tet is badly resolved. The tet's rms is
//
//   e_K = sqrt(mu_K eta_K^2 / V_K)   (T),   eta_K^2 = int_K mu_K |H* - H_h|^2 dV,
//
// the rms of |B* - B_h| over K in a linear region of permeability mu_K (air, magnets); in
// soft iron mu_K is the law's peak permeability (Material::start_permeability), an upper
// bound of the B-H curve's secant measure. Shell tets (mapped coordinates) get none: probes
// sample the physical domain only.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh3d.hpp"
#include "solver/problem3d.hpp"

namespace magfem {

// e_K (T) of every tet from its indicator eta2_J[K] (J); 0 for shell tets.
std::vector<double> tet_field_error_T(const Problem3D& problem, const std::vector<double>& eta2_J);

// A point found in the mesh: the tet holding it and where it lies in the model (metres): the
// point itself, or its mirror image in a model cut at symmetry planes.
struct TetPoint3D {
  std::size_t tet = 0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
};

// `points` (metres) found in the mesh, in point order; points outside the meshed domain are
// skipped.
std::vector<TetPoint3D> locate_points(const Mesh3D& mesh,
                                      const std::vector<Eigen::Vector3d>& points);

// The physical (non-shell) tets containing `points` (metres; at their mirror image in a model
// cut at symmetry planes), one per point found, in point order; points outside the meshed
// domain are skipped.
std::vector<std::size_t> tets_at_points(const Mesh3D& mesh,
                                        const std::vector<Eigen::Vector3d>& points);

// `seeds` and every tet reached from them through `rings` steps of sharing a vertex: the
// neighbourhood of a probe a few element sizes wide, whatever the local size. Sorted, unique.
std::vector<std::size_t> tets_near(const Mesh3D& mesh, const std::vector<std::size_t>& seeds,
                                   int rings);

// The rms of e over the tets in `tets` (one entry per probe point: a tet holding several
// points counts as often), T; 0 for none.
double rms_over(const std::vector<double>& e, const std::vector<std::size_t>& tets);

} // namespace magfem

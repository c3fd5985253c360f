#pragma once
// Goal-oriented 3D refinement for a stress-tensor force or torque named in adapt.quantities
// (adapt3d.hpp runs it). The reported force integrates T(B) over the force's surface (a sphere
// or a box in air), so its discretization error is made on that surface: the field the
// quadrature samples there. The energy's indicators do not see it: on the compensator at 90
// deg (examples/3d/compensator_adaptive.yaml) the energy estimate of the first pass was 0.06 %
// while the torque was 1.5 % off; three element layers across the 1 mm gap left it 1.46 % off
// (3.6M unknowns), a 1 mm band about the whole stress sphere put it 0.07 % off (2.8M).
// What matters is the size on the surface where the integrand's error is made (the sphere
// passes 0.5 mm from both magnets' edges), not in the gap as a whole.
//
// The local error: at each quadrature point, the difference of the point's moment (force)
// between the element B and the nodal-average B it reports, |dm_i|; the force's one-mesh
// estimate E (force3d.hpp: the spread of three fields) shared among the points in proportion,
// e_i = E |dm_i| / sum |dm|. The aim, E_aim = aim_below_target min(accuracy, estimate) |value|,
// shared by area, t_i = E_aim w_i / W. A point with e_i > t_i becomes a size source
//   h = h_K clamp((t_i / e_i)^(1 / (2 p)), min_force_ratio, 1),
// h_K the size its tet was asked to have, p the element order: the stress is quadratic in B
// and the surface integral of an order-p field's error converges like h^(2p) (measured: 1.5 %
// at the first pass's ~2 mm on the sphere, 0.07 % at 1 mm). The aim is at most half the
// estimate reached, so every pass refines where the error is largest, also once the one-mesh
// estimate is within the target but the change between passes is not yet.
#include <vector>

#include "casefile/adapt_spec.hpp"
#include "mesh/geometry3d.hpp"

namespace magfem {

struct Run3D;

// The smallest h_new / h a surface point asks for in one pass (16x the tets around it in the
// band): the first pass of the compensator asked for 0.3-0.6.
inline constexpr double min_force_ratio = 0.25;

// The size sources on the stress surfaces of the force quantities among `quantities` (energy,
// probes and Lorentz forces, which have no surface, skipped: the energy rule refines for
// them), for the accuracy `accuracy_pct`. `h_requested`: the size each tet of run's mesh was
// asked to have; `floor`: the smallest size returned. Empty when no force has an estimate.
std::vector<SizeSample3D>
force_goal_sources_3d(const Run3D& run, const std::vector<AdaptQuantity>& quantities,
                      double accuracy_pct, const std::vector<double>& h_requested, double floor);

} // namespace magfem

#pragma once
// Flux linkage of an axisymmetric coil (a region carrying N turns spread uniformly over its
// cross-section S) from the solved A_phi: each turn at (r, z) links the flux 2 pi r A_phi
// through its circle, and the turns are spread with density N / S, so
//   lambda = (N / S) integral_S 2 pi r A_phi dA        (Wb, turns included).
// The field is the total one (all coils, magnets, iron): with the coil alone in linear media,
// lambda / I is its self-inductance and lambda I / 2 the stored energy.
#include "postproc/field2d.hpp"

namespace magfem {

// part: Problem2D::parts index; S is the part's meshed area. Throws std::invalid_argument for a
// planar field (a planar region is one coil side, whose linkage needs the return side).
double flux_linkage_axi(const Field2D& field, int part, double turns);

} // namespace magfem

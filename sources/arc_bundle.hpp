#pragma once
// Field of an arc bundle: the sector phi0 <= phi <= phi1 of a thick ring of rectangular
// cross-section (the rounded corners of a racetrack coil), current circulating towards
// increasing phi. Each cross-section point carries a circular-arc filament whose field is
// integrated over the arc angle numerically (Gauss-Legendre, split at the field point's angle
// and graded towards it when the filament passes close); the cross-section integral uses the
// rules of source_quadrature.hpp. The azimuthal component is exact in closed form.
#include <vector>

#include "mesh/placement3d.hpp"
#include "sources/coil_field_options.hpp"
#include "sources/source_quadrature.hpp"

namespace magfem {

class ArcBundle {
public:
  // Centre of the ring (local frame; the ring's axis is the local z direction through it),
  // angles phi0 < phi1 (radians, from +x), radii a0 <= a <= a1, heights z0 <= z <= z1 (measured
  // from the centre); `current` (A, total through the cross-section).
  ArcBundle(const Vec3& center, double phi0, double phi1, double a0, double a1, double z0,
            double z1, double current, const CoilFieldOptions& options);

  Vec3 H(const Vec3& x) const;

private:
  struct ArcSums {
    double h_rho = 0, h_phi = 0, h_z = 0;
  };
  struct PointFrame; // the field point in the ring's cylindrical coordinates, with its arc rules
  // n_psi: order of the plain arc rule, or 0 to choose it for this filament.
  void add_arc(double a, double z, double di, const PointFrame& f, int n_psi, ArcSums& sums) const;

  // Gauss nodes of orders 1..far_order_max on [phi0, phi1]: weights and cos, sin of the angle.
  struct ArcNodes {
    std::vector<double> w, cos_phi, sin_phi;
  };

  Vec3 center_;
  double phi0_, phi1_, a0_, a1_, z0_, z1_;
  double current_density_; // A/m^2
  int graded_order_;       // points per panel of the graded arc rules
  int n_entire_;           // arc points the entire factor cos(psi) needs at the tolerance
  std::vector<ArcNodes> arc_nodes_;
  CoilFieldOptions options_;
};

} // namespace magfem

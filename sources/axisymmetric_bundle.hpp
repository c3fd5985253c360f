#pragma once
// Field of an axisymmetric bundle (a SphericalCoil or a Solenoid) as the superposition of the
// filament loops that fill its meridian cross-section. The cross-section is a rectangle in
// parameters (u, v): (r, alpha) for the spherical coil, with loops of radius r sin(alpha) at
// height r cos(alpha) and area element r dr dalpha; (rho, z) for the solenoid. Away from it the
// zonal expansions (zonal_expansion.hpp) answer when they converge, otherwise a tensor Gauss
// rule whose order follows the distance; near and inside, the split + Duffy rule of
// source_quadrature.hpp. All in the coil's local frame, for the bundle's total current.
#include <vector>

#include "mesh/coil3d.hpp"
#include "sources/coil_field_options.hpp"
#include "sources/loop_field.hpp"
#include "sources/source_quadrature.hpp"
#include "sources/zonal_expansion.hpp"

namespace magfem {

class AxisymmetricBundle {
public:
  // The bundle carries `current` amperes in total (turns times the current per turn).
  AxisymmetricBundle(const SphericalCoil& c, double current, const CoilFieldOptions& options);
  AxisymmetricBundle(const Solenoid& c, double current, const CoilFieldOptions& options);

  // Field (A/m) at meridian point (rho >= 0, z).
  MeridianField H(double rho, double z) const;
  // The same by integration over the bundle only (no expansion).
  MeridianField H_integrated(double rho, double z) const;

  // Distance from (rho, z) to the cross-section in the meridian half-plane (0 inside).
  double meridian_distance(double rho, double z) const;

  const ZonalExpansion& exterior() const { return exterior_; }
  const ZonalExpansion& interior() const { return interior_; }

private:
  struct Rule1 {
    std::vector<double> x, w, sin_x, cos_x;
  };
  void build_rules();
  void build_exterior();
  void far_orders(double rho, double z, int& nu, int& nv) const;
  void loops_at(double u, double v, double w, double& a, double& z0, double& di) const;

  bool spherical_;
  ParamRect rect_;
  double current_density_; // A/m^2 over the meridian cross-section
  CoilFieldOptions options_;
  ZonalExpansion exterior_, interior_;
  std::vector<Rule1> u_rules_, v_rules_; // index n - 1: n-point Gauss on the u and v ranges
};

} // namespace magfem

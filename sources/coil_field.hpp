#pragma once
// The free-space source field H_s of one 3D coil (mesh/coil3d.hpp) by Biot-Savart, and the
// coil's conductor geometry for the stages that integrate over it (Lorentz force, flux
// linkage, resistance). Coils are not meshed: the reduced scalar potential solver evaluates
// H_s at its quadrature points, so H() is built to be fast far from the coil (zonal expansions
// and distance-adapted rules) and accurate inside it (split + Duffy rules); see
// sources/axisymmetric_bundle.hpp, straight_bundle.hpp, arc_bundle.hpp.
//
// SI units throughout: metres, amperes, A/m, A/m^2. Points and vectors are in the global frame
// unless a name says local. Current density is uniform over the bundle's cross-section,
// |J| = turns * current / cross_section_area, circulating counter-clockwise about local +z
// for positive current.
#include <optional>
#include <vector>

#include "mesh/coil3d.hpp"
#include "sources/arc_bundle.hpp"
#include "sources/axisymmetric_bundle.hpp"
#include "sources/coil_field_options.hpp"
#include "sources/straight_bundle.hpp"

namespace magfem {

// A node of a volume rule over a coil's conductor: position, weight (m^3), and the current
// density for 1 A per turn (direction * turns / cross_section_area, A/m^2 per A).
struct CoilQuadraturePoint {
  Vec3 x;
  double weight;
  Vec3 j_per_ampere;
};

class CoilField {
public:
  // Throws std::invalid_argument for an inconsistent shape (e.g. r_outer <= r_inner).
  explicit CoilField(const Coil3D& coil, const CoilFieldOptions& options = {});

  const Coil3D& coil() const { return coil_; }

  // Field (A/m) at the coil's turns * current, and per ampere of current per turn.
  Vec3 H(const Vec3& x) const { return coil_.current * H_per_ampere(x); }
  Vec3 H_per_ampere(const Vec3& x) const;
  // The same in the coil's local frame (point and result local).
  Vec3 H_local_per_ampere(const Vec3& x_local) const;

  // Current density (A/m^2) at the coil's current; zero outside the conductor.
  Vec3 current_density(const Vec3& x) const;
  bool contains(const Vec3& x) const;

  // Bundle cross-section (m^2; the meridian cross-section of axisymmetric coils), conductor
  // volume (m^3), mean turn length = volume / cross-section (m), and DC resistance (ohm) of
  // turns^2 * mean turn length * resistivity / (fill_factor * cross-section).
  double cross_section_area() const;
  double volume() const;
  double mean_turn_length() const { return volume() / cross_section_area(); }
  double resistance() const;

  // Magnetic moment (A m^2, global frame) for 1 A per turn: turns times the area enclosed by a
  // turn averaged over the cross-section, along the coil's axis. The far field is that of
  // this dipole.
  Vec3 magnetic_moment_per_ampere() const;

  // Tensor rule over the conductor with `order` points per direction (`n_azimuth`, default
  // 2 order, equally spaced azimuths for axisymmetric coils): exact for the volume (sum of
  // weights) and for sum w j = 0 (to round-off), and of high order for smooth integrands.
  std::vector<CoilQuadraturePoint> volume_quadrature(int order, int n_azimuth = 0) const;

private:
  bool contains_local(const Vec3& xl) const;
  Vec3 direction_local(const Vec3& xl) const; // unit current direction at a conductor point

  Coil3D coil_;
  std::optional<AxisymmetricBundle> axisymmetric_;
  std::vector<StraightBundle> straights_;
  std::vector<ArcBundle> arcs_;
};

} // namespace magfem

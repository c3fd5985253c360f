#pragma once
// Field of a straight bundle of rectangular cross-section (the sides of a racetrack coil): the
// exact field of a finite straight filament, integrated over the cross-section by the rules of
// source_quadrature.hpp (tensor Gauss whose order follows the distance, split + Duffy near and
// inside). Coordinates are the coil's local frame.
#include <vector>

#include "mesh/placement3d.hpp"
#include "sources/coil_field_options.hpp"
#include "sources/source_quadrature.hpp"

namespace magfem {

// Field (A/m) at x of the filament from `start` along the unit vector `t` over `length`
// carrying `current`: H = I / (4 pi d) (cos t1 - cos t2) e_phi. Zero on the filament itself.
Vec3 straight_filament_field(const Vec3& start, const Vec3& t, double length, double current,
                             const Vec3& x);

class StraightBundle {
public:
  // The box origin + s t + p e_p + q e_q, 0 <= s <= length, 0 <= p <= width,
  // 0 <= q <= height, with e_q = t x e_p; `current` (A, total) flows along +t.
  StraightBundle(const Vec3& origin, const Vec3& t, const Vec3& e_p, double length, double width,
                 double height, double current, const CoilFieldOptions& options);

  Vec3 H(const Vec3& x) const;

private:
  // Field of the filament at cross-section point (p, q) carrying di, at the field point whose
  // coordinates are (s, px, qx); returned as the (e_p, e_q) components.
  void add_filament(double p, double q, double di, double s, double px, double qx, double& hp,
                    double& hq) const;

  Vec3 origin_, t_, e_p_, e_q_;
  double length_, width_, height_;
  double current_density_; // A/m^2
  CoilFieldOptions options_;
};

} // namespace magfem

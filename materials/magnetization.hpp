#pragma once
// Direction pattern of a permanent magnet's remanence: parallel (one direction for the whole
// part) or radial (along the position vector from a centre). The magnitude is the material's
// B_r; `sign` flips the pattern (alternating arrays). Used in 2D (z = 0) and 3D alike.
#include <cmath>

#include <Eigen/Core>

namespace magfem {

struct Magnetization {
  enum class Pattern { none, parallel, radial };
  Pattern pattern = Pattern::none;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ(); // parallel: unit vector, global frame
  Eigen::Vector3d center = Eigen::Vector3d::Zero();     // radial: origin of the rays
  double sign = 1.0;

  bool active() const { return pattern != Pattern::none; }

  // Unit direction (times sign) of the remanence at global point x; zero vector for none
  // and at the centre of a radial pattern.
  Eigen::Vector3d unit_at(const Eigen::Vector3d& x) const {
    switch (pattern) {
    case Pattern::parallel:
      return sign * direction;
    case Pattern::radial: {
      const Eigen::Vector3d d = x - center;
      const double n = d.norm();
      return n > 0 ? Eigen::Vector3d(sign * d / n) : Eigen::Vector3d::Zero();
    }
    case Pattern::none:
      break;
    }
    return Eigen::Vector3d::Zero();
  }

  // The same pattern after a rigid rotation R about point p (sweeps).
  Magnetization rotated(const Eigen::Matrix3d& r, const Eigen::Vector3d& p) const {
    Magnetization m = *this;
    m.direction = r * direction;
    m.center = r * (center - p) + p;
    return m;
  }
};

} // namespace magfem

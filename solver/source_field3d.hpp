#pragma once
// The free-space field of the coils as the 3D solver sees it: a curl-carrying source field
// H_s with curl H_s = J (Biot-Savart), linear in each coil's current. The solver never sees
// coil geometry; sources/ implements this for the coil primitives.
#include <Eigen/Core>

namespace magfem {

class SourceField3D {
public:
  virtual ~SourceField3D() = default;
  virtual int n_coils() const = 0;
  virtual double current(int coil) const = 0; // A per turn
  // Sum over the coils at their currents, A/m.
  virtual Eigen::Vector3d H(const Eigen::Vector3d& x) const = 0;
  // Coil `coil` alone at 1 A per turn (its turns included), A/m per A.
  virtual Eigen::Vector3d H_per_ampere(int coil, const Eigen::Vector3d& x) const = 0;
  // Current density of all coils at x (A/m^2), for output.
  virtual Eigen::Vector3d J(const Eigen::Vector3d& x) const = 0;
  // A scale for the source potential per ampere (the coil's turns): loop mismatches of the
  // total-potential split are compared with it.
  virtual double turns(int coil) const = 0;
};

} // namespace magfem

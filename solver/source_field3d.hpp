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
  // Every coil at 1 A per turn, out[0..n_coils()): one evaluation (or memo lookup) per point
  // where the post-processing needs all coils, instead of n_coils() of them.
  virtual void H_per_ampere_all(const Eigen::Vector3d& x, Eigen::Vector3d* out) const {
    for (int k = 0; k < n_coils(); ++k)
      out[k] = H_per_ampere(k, x);
  }
  // The same for a point that is asked for once (the rule-point table): implementations that
  // memoise points skip the memo, which would only fill with entries nobody reads again.
  virtual void H_per_ampere_all_once(const Eigen::Vector3d& x, Eigen::Vector3d* out) const {
    H_per_ampere_all(x, out);
  }
  // Current density of all coils at x (A/m^2), for output.
  virtual Eigen::Vector3d J(const Eigen::Vector3d& x) const = 0;
  // A scale for the source potential per ampere (the coil's turns): loop mismatches of the
  // total-potential split are compared with it.
  virtual double turns(int coil) const = 0;
};

} // namespace magfem

#pragma once
// The source field of all the coils of a case: the sum the reduced scalar potential solver
// needs at its quadrature points, per coil for inductances and flux linkages, and a threaded
// batch evaluation. SI units, global frame.
#include <vector>

#include "sources/coil_field.hpp"

namespace magfem {

class CoilSet {
public:
  CoilSet() = default;
  explicit CoilSet(const std::vector<Coil3D>& coils, const CoilFieldOptions& options = {});

  int size() const { return static_cast<int>(fields_.size()); }
  const CoilField& field(int coil) const { return fields_.at(static_cast<std::size_t>(coil)); }

  // Total field (A/m) of all coils at their currents, and of one coil.
  Vec3 H(const Vec3& x) const;
  Vec3 H_of(int coil, const Vec3& x) const { return field(coil).H(x); }

  // out[i] = H(points[i]) on `threads` threads (0: the hardware concurrency). Each point is
  // computed by one thread in the same order of operations, so the result does not depend on
  // the number of threads. An exception thrown by a worker is rethrown here.
  void H_at(const std::vector<Vec3>& points, std::vector<Vec3>& out, int threads = 0) const;

private:
  std::vector<CoilField> fields_;
};

} // namespace magfem

#pragma once
// The coils' source field at the quadrature points of tet_rule(rule_degree) in every tet,
// each coil per ampere, computed once (threaded) and then read by index.
// Why: the source load, the law of reduced nonlinear iron, the field energy and the flux
// linkages all integrate H_s with that rule over the whole mesh; finding each point again in a
// memo (hashing, locks, recomputation past the memo's cap) cost more than the Biot-Savart
// evaluation itself. Stored in single precision: a relative rounding of 6e-8, far below the
// 1e-4 to which the FE stages evaluate the source field (pipeline/coil_run3d.hpp).
// Shell tets hold H_s at the mapped (physical) point shell.map(x), as the shell terms use it.
// The same at the DOF points, for B at element nodes.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "solver/dof_map3d.hpp"
#include "solver/element_range.hpp"
#include "solver/problem3d.hpp"
#include "solver/source_field3d.hpp"

namespace magfem {

class SourceFieldTable3D {
public:
  static constexpr int rule_degree = 5;

  SourceFieldTable3D() = default;
  // threads: 0 = all cores (MAGFEM_THREADS). Each entry is computed on its own, so the table
  // is the same whatever the count. `share`: the tets whose entries are computed (a process's
  // share in a distributed solve; the rest stay zero until gather_to_root), and the DOF points
  // whose first tet outside the shell is one of them. `tets` (ascending), when given, in place
  // of `share`: own-row assembly's tetrahedra (solver/distributed_rows.hpp), some of which
  // other processes compute too.
  SourceFieldTable3D(const Problem3D& problem, const DofMap3D& dofs, const SourceField3D& field,
                     int threads = 0, ElementRange share = {},
                     const std::vector<std::size_t>* tets = nullptr);
  // Collective: rank 0's table becomes the whole one, every process having computed its share
  // (union_to_root: an entry computed by several processes has the same bits on each). Rank 0
  // alone post-processes; the other processes keep their share, all their element loops read.
  void gather_to_root();

  bool empty() const { return values_.empty(); }
  // Every coil's H per ampere at rule point q of tet t, out[0..n_coils).
  void H_per_ampere(std::size_t t, int q, Eigen::Vector3d* out) const;
  Eigen::Vector3d H_per_ampere(std::size_t t, int q, int coil) const;
  // The sum over the coils at their present currents.
  Eigen::Vector3d H(std::size_t t, int q) const;
  // The sum at DOF point d (B at element nodes: recovery, peak |B|; the VTU's H_s). Held for
  // the DOFs of the tets outside the shell; zero for those of the shell alone.
  Eigen::Vector3d H_at_dof(int d) const;
  std::size_t bytes() const { return values_.size() * sizeof(float); }
  // Bytes per tetrahedron and coil, for the memory estimate before meshing.
  static double bytes_per_tet_and_coil();

private:
  std::size_t index(std::size_t t, int q, int coil) const {
    return ((t * n_points_ + q) * n_coils_ + coil) * 3;
  }

  const SourceField3D* field_ = nullptr;
  int n_coils_ = 0;
  int n_points_ = 0;
  std::vector<float> values_;
  std::vector<float> at_dofs_; // per DOF and coil, per ampere
};

} // namespace magfem

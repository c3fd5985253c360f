#pragma once
// Which rows of a distributed 3D system each process owns, decided before assembly, and what
// follows from it for the process: the equations it owns and the tetrahedra it assembles
// (own-row assembly, issue 33). The rows come from a partition of the mesh (the P1 graph cut
// by PT-Scotch, the open-boundary shell whole on process 0: pmg_partition.hpp); each process
// then assembles exactly the tetrahedra that touch one of its own rows, which gives every
// entry of its rows (a row's entries come only from the tetrahedra touching its DOF) and
// nothing another process needs, so no matrix entry travels at assembly. A tetrahedron
// touching the rows of two processes is assembled by both (the ghost layer); each keeps the
// rows it owns, so the residuals summed over the processes count every tetrahedron once.
// Within a row the contributions add in element order, as serially: the sums are the serial
// ones bit for bit.
#include <cstddef>
#include <vector>

#include <Eigen/SparseCore>

#include "solver/element_range.hpp"

namespace magfem {

struct Mesh3D;
class DofMap3D;

struct DistributedRows {
  std::vector<int> order;           // row of each equation in the distributed matrix
  std::vector<int> coarse_order;    // pmg: coarse row of each P1 unknown
  std::vector<int> local_equations; // equation of each row this process owns
  int own_begin = 0, own_end = 0;   // the rows this process owns
  int coarse_local = 0;             // pmg: how many coarse rows it owns
  std::vector<std::size_t> tets;    // the tetrahedra it assembles (tets_touching_own_rows)

  bool owns(int equation) const {
    const int r = order[static_cast<std::size_t>(equation)];
    return r >= own_begin && r < own_end;
  }
};

// The lower triangle of the coupling pattern of the free vertex equations (two vertices of one
// tetrahedron; values positive, otherwise meaningless): the P1 graph the partition cuts, a few
// entries per vertex where the P2 system's pattern has ~15 per equation. P2 reads it from
// the edge DOFs, P1 from the tetrahedra: the same pattern.
Eigen::SparseMatrix<double> vertex_coupling_pattern(const Mesh3D& mesh, const DofMap3D& dofs,
                                                    const std::vector<int>& dof_to_eq);

// The tetrahedra t < n_tets (ascending) with a DOF whose equation this process owns.
std::vector<std::size_t> tets_touching_own_rows(const DofMap3D& dofs, std::size_t n_tets,
                                                const std::vector<int>& dof_to_eq,
                                                const DistributedRows& rows);

// The tetrahedra (ascending) whose coil source field this process evaluates: rows.tets, which
// its element loops read, and those of `share` (its contiguous share) with no free DOF, which
// no process assembles but rank 0's post-processing reads. Over the processes, every
// tetrahedron at least once.
std::vector<std::size_t> source_table_tets(const DofMap3D& dofs, std::size_t n_tets,
                                           const std::vector<int>& dof_to_eq,
                                           const DistributedRows& rows, ElementRange share);

} // namespace magfem

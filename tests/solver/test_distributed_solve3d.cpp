// The element shares of a distributed solve: every tetrahedron assembled by exactly one
// process, in contiguous ranges whose sizes differ by at most one, and the shares' residuals
// and tangents adding up to the whole mesh's. (The distributed solve itself runs under mpirun
// in tests/cli/test_mpi.cpp and test_mpi_solve.cpp.)
#include <gtest/gtest.h>

#include <algorithm>

#include "box_problem3d.hpp"
#include "materials/material_library.hpp"
#include "solver/distributed_solve3d.hpp"
#include "solver/dof_map3d.hpp"

namespace {

TEST(ElementShare, EveryElementOnceInBalancedContiguousRanges) {
  for (std::size_t n : {0, 1, 5, 7, 64, 78302})
    for (int size : {1, 2, 3, 8}) {
      std::size_t next = 0, smallest = n, largest = 0;
      for (int rank = 0; rank < size; ++rank) {
        const magfem::ElementRange r = magfem::element_share(n, rank, size);
        EXPECT_EQ(r.first, next) << n << " elements, rank " << rank << " of " << size;
        EXPECT_LE(r.first, r.last);
        next = r.last;
        smallest = std::min(smallest, r.last - r.first);
        largest = std::max(largest, r.last - r.first);
      }
      EXPECT_EQ(next, n) << n << " elements over " << size;
      EXPECT_LE(largest - smallest, 1u) << n << " elements over " << size;
    }
}

// Assembler3D with a share assembles exactly its tetrahedra: three shares' residuals and
// tangents (P2, saturable steel in the upper half, a magnet below, at a non-zero potential so
// that the B-H curve's slope enters the tangent) sum to the whole mesh's. Only the order of
// the sums differs: 1e-12 of the largest entry. A share that skipped or repeated a
// tetrahedron would be off by a whole element's contribution.
TEST(ElementShare, SharesResidualsAndTangentsSumToTheWholeMesh) {
  magfem::test::BoxProblem3D box(4, 2, magfem::OuterKind3D::dirichlet);
  box.problem.parts[1].material = magfem::MaterialLibrary::bundled().find("steel_1010");
  const magfem::DofMap3D dofs(box.mesh, 2);
  const magfem::Assembler3D whole(box.problem, dofs, {1, {}});
  ASSERT_FALSE(whole.is_linear());
  const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(whole.n_unknowns(), -300.0, 500.0);
  Eigen::VectorXd r_whole;
  Eigen::SparseMatrix<double> k_whole;
  whole.evaluate(u, r_whole, &k_whole, magfem::TangentKind::newton);

  constexpr int size = 3;
  Eigen::VectorXd r_sum = Eigen::VectorXd::Zero(r_whole.size());
  Eigen::SparseMatrix<double> k_sum = k_whole * 0.0;
  for (int rank = 0; rank < size; ++rank) {
    const magfem::Assembler3D share(box.problem, dofs,
                                    {1, magfem::element_share(box.mesh.n_tets(), rank, size)});
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> k;
    share.evaluate(u, r, &k, magfem::TangentKind::newton);
    EXPECT_GT((r - r_whole).norm(), 1e-3 * r_whole.norm()) << "a share is not the whole";
    r_sum += r;
    k_sum += k;
  }
  EXPECT_LE((r_sum - r_whole).cwiseAbs().maxCoeff(), 1e-12 * r_whole.cwiseAbs().maxCoeff());
  const Eigen::SparseMatrix<double> diff = k_sum - k_whole;
  double largest = 0, off = 0;
  for (int j = 0; j < k_whole.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(k_whole, j); it; ++it)
      largest = std::max(largest, std::abs(it.value()));
  for (int j = 0; j < diff.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(diff, j); it; ++it)
      off = std::max(off, std::abs(it.value()));
  EXPECT_LE(off, 1e-12 * largest);
}

} // namespace

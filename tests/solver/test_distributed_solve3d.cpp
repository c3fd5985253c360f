// The element shares of a distributed solve: every tetrahedron assembled by exactly one
// process, in contiguous ranges whose sizes differ by at most one, and the shares' residuals
// and tangents adding up to the whole mesh's. (The distributed solve itself runs under mpirun
// in tests/cli/test_mpi.cpp and test_mpi_solve.cpp.) And own-row assembly: each process's
// tetrahedra those touching its rows, whose rows then come out as the whole mesh's; and a linear
// distributed solve frees its share before the preconditioner set-up.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <numeric>
#include <string>

#include <Eigen/SparseCholesky>

#include "box_problem3d.hpp"
#include "core/progress.hpp"
#include "materials/material_library.hpp"
#include "solver/distributed_rows.hpp"
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
  const magfem::Assembler3D whole(box.problem, dofs, {1, {}, nullptr});
  ASSERT_FALSE(whole.is_linear());
  const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(whole.n_unknowns(), -300.0, 500.0);
  Eigen::VectorXd r_whole;
  Eigen::SparseMatrix<double> k_whole;
  whole.evaluate(u, r_whole, &k_whole, magfem::TangentKind::newton);

  constexpr int size = 3;
  Eigen::VectorXd r_sum = Eigen::VectorXd::Zero(r_whole.size());
  Eigen::SparseMatrix<double> k_sum = k_whole * 0.0;
  for (int rank = 0; rank < size; ++rank) {
    const magfem::Assembler3D share(
        box.problem, dofs, {1, magfem::element_share(box.mesh.n_tets(), rank, size), nullptr});
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

// The P1 graph the partition cuts: read from P2's edge DOFs it is the pattern read from the
// tetrahedra (two vertices share a tetrahedron exactly where they share an edge), with the
// constrained vertices left out alike. An edge skipped, or an entry put above the diagonal,
// changes the structure.
TEST(OwnRowAssembly, VertexPatternFromTheEdgesIsTheOneFromTheTetrahedra) {
  magfem::test::BoxProblem3D box(4, 2, magfem::OuterKind3D::dirichlet);
  const magfem::DofMap3D p2(box.mesh, 2), p1(box.mesh, 1);
  const magfem::Assembler3D whole(box.problem, p2, {1, {}, nullptr});
  const std::vector<int>& eq = whole.dof_to_equation();
  ASSERT_TRUE(std::any_of(eq.begin(), eq.begin() + p2.n_vertices(), [](int e) { return e < 0; }));
  const Eigen::SparseMatrix<double> from_edges = magfem::vertex_coupling_pattern(box.mesh, p2, eq);
  const Eigen::SparseMatrix<double> from_tets = magfem::vertex_coupling_pattern(box.mesh, p1, eq);
  ASSERT_GT(from_tets.nonZeros(), 0);
  ASSERT_EQ(from_edges.nonZeros(), from_tets.nonZeros());
  ASSERT_EQ(from_edges.outerSize(), from_tets.outerSize());
  EXPECT_TRUE(std::equal(from_edges.outerIndexPtr(),
                         from_edges.outerIndexPtr() + from_edges.outerSize() + 1,
                         from_tets.outerIndexPtr()));
  EXPECT_TRUE(std::equal(from_edges.innerIndexPtr(),
                         from_edges.innerIndexPtr() + from_edges.nonZeros(),
                         from_tets.innerIndexPtr()));
}

// Own-row assembly (solver/distributed_rows.hpp): three processes owning the equations in
// slabs along x (a partition of the mesh, as PT-Scotch's), each assembling the tetrahedra that
// touch its rows. Its own rows of the residual and the tangent are then the whole mesh's bit for
// bit: a row's entries come only from the tetrahedra touching it, all of them there, summed in the
// same element order. The own rows together are every row once, and a process's pattern is a part
// of the whole one (the memory own-row assembly saves). A tetrahedron touching two processes' rows
// assembled by one only, or a ghost tetrahedron dropped, leaves a row short.
TEST(OwnRowAssembly, OwnRowsOfEachProcessAreTheWholeMeshsRows) {
  magfem::test::BoxProblem3D box(4, 2, magfem::OuterKind3D::dirichlet);
  box.problem.parts[1].material = magfem::MaterialLibrary::bundled().find("steel_1010");
  const magfem::DofMap3D dofs(box.mesh, 2);
  const magfem::Assembler3D whole(box.problem, dofs, {1, {}, nullptr});
  const int n = whole.n_unknowns();
  const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(n, -300.0, 500.0);
  Eigen::VectorXd r_whole;
  Eigen::SparseMatrix<double> k_whole;
  whole.evaluate(u, r_whole, &k_whole, magfem::TangentKind::newton);

  // Rows in slabs along x, as a partition of the mesh gives them: equations ordered by the x
  // of their DOF point.
  std::vector<double> x(n);
  for (int d = 0; d < dofs.n_dofs(); ++d)
    if (const int eq = whole.dof_to_equation()[d]; eq >= 0)
      x[eq] = dofs.dof_points()[d].x();
  std::vector<int> by_x(n), order(n);
  std::iota(by_x.begin(), by_x.end(), 0);
  std::stable_sort(by_x.begin(), by_x.end(), [&](int a, int b) { return x[a] < x[b]; });
  for (int row = 0; row < n; ++row)
    order[by_x[row]] = row;
  constexpr int size = 3;
  std::vector<int> owners(n, 0);
  std::size_t n_assembled = 0;
  for (int rank = 0; rank < size; ++rank) {
    magfem::DistributedRows rows;
    rows.order = order;
    rows.own_begin = n * rank / size;
    rows.own_end = n * (rank + 1) / size;
    const auto tets = std::make_shared<const std::vector<std::size_t>>(
        magfem::tets_touching_own_rows(dofs, box.mesh.n_tets(), whole.dof_to_equation(), rows));
    n_assembled += tets->size();
    const magfem::Assembler3D share(box.problem, dofs, {1, {}, tets});
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> k;
    share.evaluate(u, r, &k, magfem::TangentKind::newton);
    EXPECT_LT(k.nonZeros(), k_whole.nonZeros()) << "rank " << rank;
    for (int i = 0; i < n; ++i)
      if (rows.owns(i)) {
        ++owners[i];
        EXPECT_EQ(r[i], r_whole[i]) << "residual row " << i << ", rank " << rank;
      }
    // Every lower entry (i, j) in an own row (i, or j by symmetry).
    for (int j = 0; j < k_whole.outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(k_whole, j); it; ++it)
        if (rows.owns(static_cast<int>(it.row())) || rows.owns(j)) {
          ASSERT_EQ(k.coeff(it.row(), j), it.value())
              << "entry (" << it.row() << ", " << j << "), rank " << rank;
        }
  }
  EXPECT_EQ(std::count(owners.begin(), owners.end(), 1), n);
  // The ghost layer: some tetrahedra assembled twice, not all.
  EXPECT_GT(n_assembled, box.mesh.n_tets());
  EXPECT_LT(n_assembled, 2 * box.mesh.n_tets());
}

} // namespace

// A linear distributed solve lets its share of the tetrahedra go (the assembler's pattern and
// scatter table) after the one assembly, before the preconditioner's set-up, where a
// process's memory peaks (issue 33: a sixth of benchmark32's peak per process); and its
// solution is still the system's. One process (an MPI singleton) runs the distributed code
// path: the same load, set-up and CG over MPI_COMM_WORLD. The box (magnet and linear iron),
// P1, CG + BoomerAMG to 1e-12 against a direct solve: the solution to 1e-8 of its largest
// value (CG's residual 1e-12 times the box's condition number, ~1e3 at 4 cells a side).
class ShareAtSetUp : public magfem::Progress {
public:
  explicit ShareAtSetUp(std::weak_ptr<const magfem::Assembler3D> share)
      : Progress(nullptr), share_(std::move(share)) {}
  void stage(const std::string& what) override {
    if (what.rfind("preconditioner set-up", 0) == 0) {
      seen = true;
      alive = !share_.expired();
    }
  }
  void iteration(const char*, int, double) override {}
  void note(const std::string&) override {}
  bool seen = false, alive = true;

private:
  std::weak_ptr<const magfem::Assembler3D> share_;
};

TEST(DistributedSolve, LinearSolveFreesItsShareBeforeThePreconditionerSetUp) {
  magfem::test::BoxProblem3D box(4, 1, magfem::OuterKind3D::dirichlet);
  const magfem::DofMap3D dofs(box.mesh, 1);
  auto share = std::make_shared<const magfem::Assembler3D>(
      box.problem, dofs, magfem::AssemblyOptions3D{1, {}, nullptr});
  ASSERT_TRUE(share->is_linear());
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> k;
  share->evaluate(Eigen::VectorXd::Zero(share->n_unknowns()), r, &k, magfem::TangentKind::newton);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> direct(k);
  const Eigen::VectorXd expected = direct.solve(-r);

  ShareAtSetUp progress(share);
  magfem::NewtonOptions options;
  options.linear.preconditioner = magfem::PreconditionerKind::boomeramg;
  options.linear.cg_tolerance = 1e-12;
  options.linear.progress = &progress;
  Eigen::VectorXd u;
  const magfem::NewtonReport report = magfem::solve_distributed(std::move(share), 1, options, u);
  ASSERT_TRUE(report.converged);
  EXPECT_TRUE(progress.seen);
  EXPECT_FALSE(progress.alive) << "the share outlived the assembly";
  ASSERT_EQ(u.size(), expected.size());
  EXPECT_LE((u - expected).cwiseAbs().maxCoeff(), 1e-8 * expected.cwiseAbs().maxCoeff());
}

// The distributed p-multigrid's coarse operator (solver/distributed_galerkin_product.hpp)
// entry by entry against the serial product (galerkin_product.hpp): under mpirun -n 1, 2 and 3,
// a fine matrix whose rows the processes own in an interleaved order (as the mesh partition
// gives them) and coarse rows numbered in another, so that every process's share has rows that
// other processes own (the exchange) and columns off its own block (the off-diagonal block).
// Each process adds its own coarse rows into a dense copy, process 0 sums the copies and
// compares with P^T A P renumbered; the sums add in another order than serially, so they agree
// to rounding (1e-13 of the largest entry), not bit for bit. The solve that uses it:
// tests/cli/test_mpi.cpp (iterations and fields against serial).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <petscsys.h>

#include <Eigen/Dense>

#include "solver/distributed_galerkin_product.hpp"
#include "solver/galerkin_product.hpp"
#include "tests/cli/mpi_helpers.hpp"
#include "tests/solver/petsc_module_test.hpp"

namespace fs = std::filesystem;

namespace magfem::petsc_module {

namespace {

constexpr int n = 240; // fine equations
constexpr int m = 45;  // coarse (P1) unknowns

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// A symmetric fine matrix with couplings near and far in equation order (the same on every
// process: fixed seed).
Eigen::SparseMatrix<double, Eigen::RowMajor> fine_matrix() {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 8.0 + u(random));
    for (int step : {1, 7, 61}) {
      const int j = (i + step) % n;
      const double v = u(random);
      t.emplace_back(i, j, v);
      t.emplace_back(j, i, v);
    }
  }
  RowMajor a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

// As pmg's interpolation: every fine row one or two entries.
RowMajor interpolation() {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i % m, 1.0);
    if (i % 3 == 0)
      t.emplace_back(i, (7 * i + 11) % m, 0.5 + 0.01 * (i % 5));
  }
  RowMajor p(n, m);
  p.setFromTriplets(t.begin(), t.end());
  return p;
}

// Rows numbered process by process, in item order within: order[k] is item k's row; the
// range [begin, end) this process owns; its items in row order.
struct Numbering {
  std::vector<int> order, mine;
  int begin = 0, end = 0;
};

Numbering numbering(int items, int size, int rank) {
  Numbering r;
  r.order.assign(static_cast<std::size_t>(items), -1);
  int next = 0;
  for (int p = 0; p < size; ++p) {
    if (p == rank)
      r.begin = next;
    for (int k = 0; k < items; ++k)
      if (interleaved_process(k, size) == p) {
        r.order[static_cast<std::size_t>(k)] = next++;
        if (p == rank)
          r.mine.push_back(k);
      }
    if (p == rank)
      r.end = next;
  }
  return r;
}

// The child: under mpirun, each process's coarse rows of the distributed product summed into
// process 0's dense copy, compared there; the report goes to the folder MAGFEM_GALERKIN_CHILD
// names.
TEST(DistributedGalerkinChild, ReportsTheDifferenceToTheSerialProduct) {
  const char* out = std::getenv("MAGFEM_GALERKIN_CHILD");
  if (!out)
    GTEST_SKIP() << "run by the test below under mpirun";
  const auto [size, rank] = start_petsc_child();
  const RowMajor a = fine_matrix();
  const RowMajor p = interpolation();
  const Numbering fine = numbering(n, size, rank);
  const Numbering coarse = numbering(m, size, rank);
  PmgPartition rows;
  rows.order = fine.order;
  rows.coarse_order = coarse.order;
  rows.local_equations = fine.mine;
  rows.own_begin = fine.begin;
  rows.own_end = fine.end;
  rows.coarse_local = coarse.end - coarse.begin;
  // This process's rows of A, in the distributed numbering, columns sorted.
  std::vector<PetscInt> row_start{0}, column;
  std::vector<PetscScalar> value;
  for (int e : fine.mine) {
    std::vector<std::pair<int, double>> entries;
    for (RowMajor::InnerIterator k(a, e); k; ++k)
      entries.emplace_back(fine.order[static_cast<std::size_t>(k.col())], k.value());
    std::sort(entries.begin(), entries.end());
    for (const auto& [c, v] : entries) {
      column.push_back(c);
      value.push_back(v);
    }
    row_start.push_back(static_cast<PetscInt>(column.size()));
  }
  Mat fine_mat = nullptr;
  ASSERT_EQ(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, fine.end - fine.begin,
                                      fine.end - fine.begin, n, n, row_start.data(), column.data(),
                                      value.data(), &fine_mat),
            0);
  Mat c = distributed_galerkin_product(fine_mat, p, rows, coarse.begin, coarse.end);
  Eigen::MatrixXd mine = Eigen::MatrixXd::Zero(m, m), sum = Eigen::MatrixXd::Zero(m, m);
  for (PetscInt r = coarse.begin; r < coarse.end; ++r) {
    PetscInt count = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    MatGetRow(c, r, &count, &cols, &vals);
    for (PetscInt k = 0; k < count; ++k)
      mine(r, cols[k]) = vals[k];
    MatRestoreRow(c, r, &count, &cols, &vals);
  }
  MPI_Reduce(mine.data(), sum.data(), m * m, MPI_DOUBLE, MPI_SUM, 0, PETSC_COMM_WORLD);
  // The coarse rows the processes own, together (each once: m).
  int owned = coarse.end - coarse.begin, total_owned = 0;
  MPI_Reduce(&owned, &total_owned, 1, MPI_INT, MPI_SUM, 0, PETSC_COMM_WORLD);
  MatDestroy(&c);
  MatDestroy(&fine_mat);
  if (rank == 0) {
    const RowMajor full = a; // both triangles, as galerkin_product reads them
    const CsrMatrix serial =
        galerkin_product(full.outerIndexPtr(), full.innerIndexPtr(), full.valuePtr(), p, 1);
    Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(m, m);
    for (int i = 0; i < m; ++i)
      for (int k = serial.row_start[static_cast<std::size_t>(i)];
           k < serial.row_start[static_cast<std::size_t>(i) + 1]; ++k)
        expected(
            coarse.order[static_cast<std::size_t>(i)],
            coarse.order[static_cast<std::size_t>(serial.column[static_cast<std::size_t>(k)])]) =
            serial.value[static_cast<std::size_t>(k)];
    std::ofstream(fs::path(out) / "report")
        << "rows " << total_owned << "\nrelative difference "
        << (sum - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff() << "\n";
  }
  PetscFinalize();
}

class DistributedGalerkin : public ::testing::Test {
protected:
  void SetUp() override {
    if (const std::string why = test::why_no_mpi_children("MAGFEM_GALERKIN_CHILD"); !why.empty())
      GTEST_SKIP() << why;
  }

  // The child's report under `mpirun -n <size>`: the coarse rows it assembled and the largest
  // difference relative to the largest entry.
  std::pair<int, double> run(int size) {
    const fs::path dir = test::fresh_dir("galerkin_" + std::to_string(size));
    const test::CliOutcome o =
        test::run_mpi_children(size, "DistributedGalerkinChild.*", "MAGFEM_GALERKIN_CHILD", dir);
    EXPECT_EQ(o.status, 0) << o.out;
    std::ifstream in(dir / "report");
    std::string word;
    int rows = -1;
    double difference = 1;
    in >> word >> rows >> word >> word >> difference;
    EXPECT_TRUE(in) << o.out;
    fs::remove_all(dir);
    return {rows, difference};
  }
};

// 1e-13: a few hundred products summed in another order (the shares) differ in the last bits
// of entries of order 10; a dropped, misrouted or doubled share differs by O(1).
TEST_F(DistributedGalerkin, EqualsTheSerialProductOnOneTwoAndThreeProcesses) {
  for (int size : {1, 2, 3}) {
    const auto [rows, difference] = run(size);
    EXPECT_EQ(rows, m) << size << " processes: every coarse row owned once";
    EXPECT_LT(difference, 1e-13) << size << " processes";
  }
}

} // namespace
} // namespace magfem::petsc_module

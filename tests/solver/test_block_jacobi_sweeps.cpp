// pmg's distributed fine-level smoother (solver/block_jacobi_sweeps.hpp) against the same
// sweeps done serially: under mpirun -n 1, 2 and 3, a symmetric matrix whose rows the
// processes own in an interleaved order (own_row_matrix, as the mesh partition gives them),
// a block solved exactly on process 0 (the open-boundary shell), and two sweeps from a guess
// that is not zero. The reference is block Jacobi across the processes written out on every
// process from the whole matrix: each process's rows swept by a BlockSmoother of its own
// diagonal block, built from the matrix directly (not from PETSc's), with the right-hand side
// b - A_off x from the values all processes had at the start of the sweep. The smoother
// itself is tested against Gauss-Seidel by hand in test_block_smoother.cpp; what this one
// checks is the distribution: the other processes' values (their gather, sign and columns),
// the sweeps counted, and the zero guess on the first sweep only. The solve that uses it:
// tests/cli/test_mpi_solve.cpp (iterations and fields against serial).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <petscmat.h>

#include <Eigen/Dense>

#include "solver/block_jacobi_sweeps.hpp"
#include "solver/own_row_matrix.hpp"
#include "tests/cli/mpi_helpers.hpp"
#include "tests/solver/petsc_module_test.hpp"

namespace fs = std::filesystem;

namespace magfem::petsc_module {

namespace {

constexpr int n = 150;         // equations
constexpr int block_rows = 12; // process 0's first rows: the block it solves exactly

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// The distributed row of each equation (process by process, equation order within), and
// where each process's rows start; the matrix below is written in these rows.
struct Rows {
  std::vector<PetscInt> order;
  std::vector<int> start; // size + 1
};

Rows rows_of(int size) {
  Rows r;
  r.order.assign(n, -1);
  r.start.push_back(0);
  int next = 0;
  for (int p = 0; p < size; ++p) {
    for (int k = 0; k < n; ++k)
      if (interleaved_process(k, size) == p)
        r.order[k] = next++;
    r.start.push_back(next);
  }
  return r;
}

// Symmetric and diagonally dominant (so the block is positive definite), couplings near and
// far in equation order, so that every process's rows read other processes' unknowns; the
// same on every process (fixed seed). In equation numbering.
Eigen::MatrixXd whole_matrix() {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    a(i, i) += 8.0 + u(random);
    for (int step : {1, 5, 43}) {
      const int j = (i + step) % n;
      const double v = u(random);
      a(i, j) += v;
      a(j, i) += v;
    }
  }
  return a;
}

Eigen::VectorXd random_vector(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i)
    v[i] = u(random);
  return v;
}

// The block of process p's rows, as a CSR of its own (columns sorted), from the matrix in
// distributed rows.
struct LocalBlock {
  std::vector<PetscInt> row_start{0}, column;
  std::vector<PetscScalar> value;
  CsrView view() const {
    return {static_cast<PetscInt>(row_start.size()) - 1, row_start.data(), column.data(),
            value.data()};
  }
};

LocalBlock local_block(const Eigen::MatrixXd& a, int begin, int end) {
  LocalBlock b;
  for (int i = begin; i < end; ++i) {
    for (int j = begin; j < end; ++j)
      if (a(i, j) != 0) {
        b.column.push_back(j - begin);
        b.value.push_back(a(i, j));
      }
    b.row_start.push_back(static_cast<PetscInt>(b.column.size()));
  }
  return b;
}

std::vector<int> block_of(int process) {
  std::vector<int> block;
  if (process == 0)
    for (int i = 0; i < block_rows; ++i)
      block.push_back(i);
  return block;
}

// One case: `sweeps` steps down or up, from x0 or from zero.
struct Case {
  bool down, zero_guess;
  int sweeps;
};

// Block Jacobi across the processes, serially: every process's rows swept from the values of
// the previous sweep (`a`, `b`, `x` in distributed rows).
Eigen::VectorXd reference(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, Eigen::VectorXd x,
                          const Rows& rows, const Case& c) {
  const int size = static_cast<int>(rows.start.size()) - 1;
  if (c.zero_guess)
    x.setZero();
  for (int sweep = 0; sweep < c.sweeps; ++sweep) {
    const Eigen::VectorXd before = x;
    for (int p = 0; p < size; ++p) {
      const int begin = rows.start[p], end = rows.start[p + 1];
      Eigen::VectorXd rhs = b.segment(begin, end - begin);
      for (int i = begin; i < end; ++i)
        for (int j = 0; j < n; ++j)
          if (j < begin || j >= end)
            rhs[i - begin] -= a(i, j) * before[j];
      const LocalBlock block = local_block(a, begin, end);
      BlockFactorCache cache;
      BlockSmoother smoother(block.view(), block_of(p), cache);
      Eigen::VectorXd mine = before.segment(begin, end - begin);
      smoother.smooth(rhs.data(), mine.data(), c.down, c.zero_guess && sweep == 0, 1, 1);
      x.segment(begin, end - begin) = mine;
    }
  }
  return x;
}

// Each case's distributed sweeps against the reference: the largest difference over all
// processes, relative to the largest value. Collective; PETSc's objects all gone on return.
double largest_difference(int size, int rank) {
  const Rows rows = rows_of(size);
  // The matrix, b and x0 in distributed rows: a_d(order[i], order[j]) = a(i, j).
  const Eigen::MatrixXd a = whole_matrix();
  Eigen::MatrixXd a_d(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      a_d(rows.order[i], rows.order[j]) = a(i, j);
  const Eigen::VectorXd b = random_vector(3), x0 = random_vector(5);
  // PETSc's matrix as the solve makes it, from the lower triangle in equations.
  const Eigen::SparseMatrix<double> lower =
      a.triangularView<Eigen::Lower>().toDenseMatrix().sparseView();
  PmgPartition partition;
  partition.order = rows.order;
  partition.own_begin = rows.start[rank];
  partition.own_end = rows.start[rank + 1];
  const int begin = partition.own_begin, local = partition.own_end - begin;
  Mat matrix = own_row_matrix(lower, partition);
  Mat diag = nullptr, off = nullptr;
  const PetscInt* off_columns = nullptr;
  check(MatMPIAIJGetSeqAIJ(matrix, &diag, &off, &off_columns), "MatMPIAIJGetSeqAIJ");
  const PetscInt *ia = nullptr, *ja = nullptr;
  PetscScalar* v = nullptr;
  PetscMemType memory = PETSC_MEMTYPE_HOST;
  check(MatSeqAIJGetCSRAndMemType(diag, &ia, &ja, &v, &memory), "MatSeqAIJGetCSRAndMemType");
  BlockFactorCache cache;
  BlockSmoother smoother({local, ia, ja, v}, block_of(rank), cache);
  Vec vb = nullptr, vx = nullptr;
  check(MatCreateVecs(matrix, &vx, &vb), "MatCreateVecs");
  double worst = 0;
  {
    OffProcessRows off_process(matrix);
    for (const Case c :
         {Case{true, false, 2}, Case{false, false, 2}, Case{true, true, 2}, Case{false, true, 1}}) {
      {
        const WriteArray own_b(vb), own_x(vx);
        for (int i = 0; i < local; ++i) {
          own_b.data()[i] = b[begin + i];
          own_x.data()[i] = x0[begin + i];
        }
      }
      smooth_block_jacobi(smoother, &off_process, vb, vx, c.down, c.zero_guess, c.sweeps, 1);
      const Eigen::VectorXd expected = reference(a_d, b, x0, rows, c);
      double difference = 0;
      {
        const ReadArray own_x(vx);
        for (int i = 0; i < local; ++i)
          difference = std::max(difference, std::abs(own_x.data()[i] - expected[begin + i]));
      }
      difference /= expected.cwiseAbs().maxCoeff();
      MPI_Allreduce(MPI_IN_PLACE, &difference, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
      worst = std::max(worst, difference);
    }
  }
  VecDestroy(&vb);
  VecDestroy(&vx);
  MatDestroy(&matrix);
  return worst;
}

// The child: under mpirun, the report goes to the folder MAGFEM_SWEEPS_CHILD names.
TEST(BlockJacobiSweepsChild, ReportsTheDifferenceToSerialBlockJacobi) {
  const char* out = std::getenv("MAGFEM_SWEEPS_CHILD");
  if (!out)
    GTEST_SKIP() << "run by the test below under mpirun";
  ASSERT_EQ(PetscInitializeNoArguments(), 0);
  int size = 1, rank = 0;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  const double worst = largest_difference(size, rank);
  if (rank == 0)
    std::ofstream(fs::path(out) / "report") << "relative difference " << worst << "\n";
  PetscFinalize();
}

class BlockJacobiSweeps : public ::testing::Test {
protected:
  void SetUp() override {
    if (const std::string why = test::why_no_mpi_children("MAGFEM_SWEEPS_CHILD"); !why.empty())
      GTEST_SKIP() << why;
  }

  // The child's largest difference under `mpirun -n <size>`, relative to the largest value.
  double run(int size) {
    const fs::path dir = test::fresh_dir("sweeps_" + std::to_string(size));
    const test::CliOutcome o =
        test::run_mpi_children(size, "BlockJacobiSweepsChild.*", "MAGFEM_SWEEPS_CHILD", dir);
    EXPECT_EQ(o.status, 0) << o.out;
    std::ifstream in(dir / "report");
    std::string word;
    double difference = 1;
    in >> word >> word >> difference;
    EXPECT_TRUE(in) << o.out;
    fs::remove_all(dir);
    return difference;
  }
};

// 1e-13: the right-hand side's few products per row summed in another order than PETSc's
// product of the off-diagonal block; other processes' values left out, taken with the wrong
// sign or from the wrong columns, a sweep too few or a zero guess on every sweep differ by
// O(0.1).
TEST_F(BlockJacobiSweeps, EqualSerialBlockJacobiOnOneTwoAndThreeProcesses) {
  for (int size : {1, 2, 3})
    EXPECT_LT(run(size), 1e-13) << size << " processes";
}

} // namespace
} // namespace magfem::petsc_module

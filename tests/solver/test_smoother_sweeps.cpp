// pmg's fine-level smoother distributed (solver/smoother_sweeps.hpp) against the same sweep
// written out serially: under mpirun -n 1, 2 and 3, a symmetric matrix whose rows the
// processes own in an interleaved order (own_row_matrix, as the mesh partition gives them), a
// block solved exactly on process 0 (the open-boundary shell), sweeps down and up, from a
// guess that is not zero and from zero. The reference, on every process from the whole dense
// matrix, is one Gauss-Seidel sweep over all rows in the order the header names: the block
// (solved exactly), every process's rows that read no other process's unknowns (those near
// the block after the others), then the rows that do, process 0's first; up the same
// backwards, the block last. It differs from block Jacobi across the processes (each process
// from the others' old values: 22 CG iterations on benchmark32 against serial 20) in the
// last digits only where the processes' rows couple, so the tolerance is tight. What this
// checks is the distribution: the other processes' values (their gather, sign and columns),
// the order of the processes' last rows, up as the transpose of down, the sweeps counted and
// the zero guess on the first sweep only. The solve that uses it: tests/cli/test_mpi_solve.cpp
// (iterations and fields against serial).
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

#include "solver/own_row_matrix.hpp"
#include "solver/smoother_sweeps.hpp"
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

// The rows of one process in the sweep's groups (distributed rows, ascending).
struct Groups {
  std::vector<int> block, far, near, reading;
};

// Process p's groups: the block (block_of), rows reading other processes' unknowns, rows
// coupled to the block, the others.
Groups groups_of(const Eigen::MatrixXd& a, const Rows& rows, int p) {
  const int begin = rows.start[p], end = rows.start[p + 1];
  const std::vector<int> local_block = block_of(p);
  Groups g;
  for (int k : local_block)
    g.block.push_back(begin + k);
  const auto in_block = [&](int j) {
    return std::find(g.block.begin(), g.block.end(), j) != g.block.end();
  };
  for (int i = begin; i < end; ++i) {
    if (in_block(i))
      continue;
    bool reads_others = false, near = false;
    for (int j = 0; j < n; ++j)
      if (a(i, j) != 0) {
        reads_others |= j < begin || j >= end;
        near |= in_block(j);
      }
    (reads_others ? g.reading : near ? g.near : g.far).push_back(i);
  }
  return g;
}

void relax(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, Eigen::VectorXd& x, int i) {
  x[i] += (b[i] - a.row(i).dot(x)) / a(i, i);
}

void forward(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
             const std::vector<int>& rows) {
  for (int i : rows)
    relax(a, b, x, i);
}

void backward(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
              const std::vector<int>& rows) {
  for (auto i = rows.rbegin(); i != rows.rend(); ++i)
    relax(a, b, x, *i);
}

// x_B += A_BB^-1 (b - A x)_B
void solve_block(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                 const std::vector<int>& block) {
  if (block.empty())
    return;
  const auto m = static_cast<Eigen::Index>(block.size());
  Eigen::MatrixXd abb(m, m);
  Eigen::VectorXd r(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    r[k] = b[block[k]] - a.row(block[k]).dot(x);
    for (Eigen::Index l = 0; l < m; ++l)
      abb(k, l) = a(block[k], block[l]);
  }
  const Eigen::VectorXd dx = abb.llt().solve(r);
  for (Eigen::Index k = 0; k < m; ++k)
    x[block[k]] += dx[k];
}

// The sweeps over the whole system in the order above (`a`, `b`, `x` in distributed rows).
Eigen::VectorXd reference(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, Eigen::VectorXd x,
                          const Rows& rows, const Case& c) {
  const int size = static_cast<int>(rows.start.size()) - 1;
  std::vector<Groups> g;
  for (int p = 0; p < size; ++p)
    g.push_back(groups_of(a, rows, p));
  if (c.zero_guess)
    x.setZero();
  for (int sweep = 0; sweep < c.sweeps; ++sweep) {
    if (c.down) {
      for (int p = 0; p < size; ++p) {
        solve_block(a, b, x, g[p].block);
        forward(a, b, x, g[p].far);
        forward(a, b, x, g[p].near);
      }
      for (int p = 0; p < size; ++p)
        forward(a, b, x, g[p].reading);
    } else {
      for (int p = size - 1; p >= 0; --p)
        backward(a, b, x, g[p].reading);
      for (int p = 0; p < size; ++p) {
        backward(a, b, x, g[p].near);
        backward(a, b, x, g[p].far);
        solve_block(a, b, x, g[p].block);
      }
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
  OffProcessRows off_process(matrix);
  smoother.put_last(off_process.reading_rows());
  Vec vb = nullptr, vx = nullptr;
  check(MatCreateVecs(matrix, &vx, &vb), "MatCreateVecs");
  double worst = 0;
  {
    for (const Case c :
         {Case{true, false, 2}, Case{false, false, 2}, Case{true, true, 2}, Case{false, true, 1}}) {
      {
        const WriteArray own_b(vb), own_x(vx);
        for (int i = 0; i < local; ++i) {
          own_b.data()[i] = b[begin + i];
          own_x.data()[i] = x0[begin + i];
        }
      }
      smooth_sweeps(smoother, &off_process, vb, vx, c.down, c.zero_guess, c.sweeps, 1);
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
TEST(SmootherSweepsChild, ReportsTheDifferenceToTheSerialSweep) {
  const char* out = std::getenv("MAGFEM_SWEEPS_CHILD");
  if (!out)
    GTEST_SKIP() << "run by the test below under mpirun";
  const auto [size, rank] = start_petsc_child();
  const double worst = largest_difference(size, rank);
  if (rank == 0)
    std::ofstream(fs::path(out) / "report") << "relative difference " << worst << "\n";
  PetscFinalize();
}

class SmootherSweeps : public ::testing::Test {
protected:
  void SetUp() override {
    if (const std::string why = test::why_no_mpi_children("MAGFEM_SWEEPS_CHILD"); !why.empty())
      GTEST_SKIP() << why;
  }

  // The child's largest difference under `mpirun -n <size>`, relative to the largest value.
  double run(int size) {
    const fs::path dir = test::fresh_dir("sweeps_" + std::to_string(size));
    const test::CliOutcome o =
        test::run_mpi_children(size, "SmootherSweepsChild.*", "MAGFEM_SWEEPS_CHILD", dir);
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

// 1e-13: sums of a few products per row in another order (PETSc's blocks against dense rows)
// and the 12 x 12 block by CHOLMOD against a dense Cholesky differ in the last bits; block
// Jacobi across the processes, the processes' last rows in another order, a missing gather,
// b + A_off x, a sweep too few or a zero guess on every sweep differ by 1e-3 or more.
TEST_F(SmootherSweeps, EqualsTheSerialSweepOnOneTwoAndThreeProcesses) {
  for (int size : {1, 2, 3})
    EXPECT_LT(run(size), 1e-13) << size << " processes";
}

} // namespace
} // namespace magfem::petsc_module

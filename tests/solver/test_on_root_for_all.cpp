// Work process 0 does alone for all (solver/on_root_for_all.hpp: the mesh's partition of the
// distributed solve) under mpirun -n 2 and 3: done once, on process 0; and when it throws,
// whatever it throws, every process throws alike (process 0 its message, the others naming
// what failed where) rather than waiting for ever. A hang would show as mpirun's timeout.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <petscsys.h>

#include "solver/on_root_for_all.hpp"
#include "tests/cli/mpi_helpers.hpp"

namespace fs = std::filesystem;

namespace magfem::petsc_module {
namespace {

// The child: each process's outcome, written to rank.<r> in the folder MAGFEM_ROOT_CHILD
// names; MAGFEM_ROOT_THROW = std | int | (empty) makes process 0's work throw.
TEST(OnRootForAllChild, WritesThisProcesssOutcome) {
  const char* out = std::getenv("MAGFEM_ROOT_CHILD");
  if (!out)
    GTEST_SKIP() << "run by the tests below under mpirun";
  const std::string kind = std::getenv("MAGFEM_ROOT_THROW") ? std::getenv("MAGFEM_ROOT_THROW") : "";
  ASSERT_EQ(PetscInitializeNoArguments(), 0);
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  int runs = 0;
  std::string outcome;
  try {
    on_root_for_all(PETSC_COMM_WORLD, "the mesh's partition", [&] {
      ++runs;
      if (kind == "std")
        throw std::runtime_error("Scotch ran out of memory");
      if (kind == "int")
        throw 42;
    });
    outcome = "done";
  } catch (const SolveError& e) {
    outcome = std::string("error ") + e.what();
  }
  // Every process still answers a collective call afterwards: none is left inside the first.
  int all = 0;
  MPI_Allreduce(&runs, &all, 1, MPI_INT, MPI_SUM, PETSC_COMM_WORLD);
  std::ofstream(fs::path(out) / ("rank." + std::to_string(rank)))
      << "ran " << runs << " of " << all << "\n"
      << outcome << "\n";
  PetscFinalize();
}

class OnRootForAll : public ::testing::Test {
protected:
  void SetUp() override {
    if (const std::string why = test::why_no_mpi_children("MAGFEM_ROOT_CHILD"); !why.empty())
      GTEST_SKIP() << why;
  }

  std::vector<std::string> run(int n, const std::string& kind) {
    const fs::path dir = test::fresh_dir("root_" + std::to_string(n) + kind);
    const test::CliOutcome o = test::run_mpi_children(n, "OnRootForAllChild.*", "MAGFEM_ROOT_CHILD",
                                                      dir, {{"MAGFEM_ROOT_THROW", kind}}, 60);
    EXPECT_EQ(o.status, 0) << o.out; // 124: mpirun's timeout, a process left waiting
    std::vector<std::string> reports;
    for (int r = 0; r < n; ++r)
      reports.push_back(test::text_of(dir / ("rank." + std::to_string(r))));
    fs::remove_all(dir);
    return reports;
  }
};

TEST_F(OnRootForAll, TheWorkRunsOnceOnProcessZero) {
  const auto reports = run(3, "");
  EXPECT_EQ(reports[0], "ran 1 of 1\ndone\n");
  EXPECT_EQ(reports[1], "ran 0 of 1\ndone\n");
  EXPECT_EQ(reports[2], "ran 0 of 1\ndone\n");
}

TEST_F(OnRootForAll, AFailureOnProcessZeroFailsEveryProcess) {
  const auto reports = run(2, "std");
  EXPECT_EQ(reports[0], "ran 1 of 1\nerror Scotch ran out of memory\n");
  EXPECT_EQ(reports[1], "ran 0 of 1\nerror the mesh's partition failed on process 0\n");
  const auto odd = run(3, "int");
  EXPECT_EQ(odd[0], "ran 1 of 1\nerror the mesh's partition failed on process 0 (an exception "
                    "that is not a std::exception)\n");
  EXPECT_EQ(odd[2], "ran 0 of 1\nerror the mesh's partition failed on process 0\n");
}

} // namespace
} // namespace magfem::petsc_module

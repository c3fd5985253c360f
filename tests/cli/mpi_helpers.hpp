#pragma once
// What the tests that run magfem under mpirun share (test_mpi.cpp: the distributed solve and
// sweep; test_mpi_solve.cpp: coils and nonlinear iron; test_mpi_studies.cpp: study, validate,
// actuator --verify): the launcher, fresh output folders, and the comparison of a distributed
// run's outputs with a serial run's.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "postproc/probe_compare.hpp"
#include "tests/run_cli.hpp"

namespace magfem::test {

namespace fs = std::filesystem;

// A fresh output folder of this test process (several worktrees may run the suite at once).
inline fs::path fresh_dir(const std::string& name) {
  const auto dir =
      fs::temp_directory_path() / "magfem_tests" / ("mpi_" + std::to_string(getpid())) / name;
  fs::remove_all(dir);
  return dir;
}

inline std::string mpirun_path() {
  for (const char* dir : {"/usr/bin", "/usr/local/bin", "/bin"})
    if (fs::exists(fs::path(dir) / "mpirun"))
      return (fs::path(dir) / "mpirun").string();
  return "";
}

// `mpirun -n <n> magfem <args>`, stdout and stderr together. Open MPI refuses to run as root
// unless told twice: the option (1.x-4.x) and the environment (4.x and later) cover both. A
// process left waiting for another would hang the test: `timeout` ends it (exit 124). The
// default catches a hang, not slowness: it stays inside ctest's 600 s, and leaves room for a
// machine whose cores builds share (CI saw an FE study that takes 15 s alone take over 120 s
// under a load of 16).
// `mpirun_options` go to mpirun itself (e.g. a binding).
// `program` is a command line of its own (run_mpi_program: e.g. a test executable).
inline CliOutcome run_mpi_program(int n, const std::string& program, int timeout_s = 400,
                                  const std::string& mpirun_options = "") {
  std::string cmd = "timeout " + std::to_string(timeout_s) + " " + mpirun_path() + " -n " +
                    std::to_string(n) + " --oversubscribe " + mpirun_options + " ";
  if (geteuid() == 0) {
    cmd += "--allow-run-as-root ";
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  }
  return run_command(cmd + program);
}
// Tests that run a child test of their own executable under mpirun (a unit of the PETSc
// module or the pipeline on several processes, without magfem around it): the child reads its
// output folder from the environment variable `folder_variable` and skips without it.
// Why the parent test cannot run here, or "" when it can.
inline std::string why_no_mpi_children(const char* folder_variable) {
  if (mpirun_path().empty())
    return "mpirun not found (Debian: mpi-default-bin, scripts/install_deps.sh)";
  if (std::getenv(folder_variable))
    return "the child runs only its own test";
  return "";
}

// `mpirun -n <n>` of this executable's tests `filter`, `folder` (created) named to them in
// `folder_variable` and `variables` set for them; all unset again afterwards.
inline CliOutcome run_mpi_children(
    int n, const std::string& filter, const char* folder_variable, const fs::path& folder,
    const std::vector<std::pair<std::string, std::string>>& variables = {}, int timeout_s = 120) {
  fs::create_directories(folder);
  setenv(folder_variable, folder.c_str(), 1);
  for (const auto& [name, value] : variables)
    setenv(name.c_str(), value.c_str(), 1);
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  CliOutcome o = run_mpi_program(n, self + " --gtest_filter=" + filter, timeout_s);
  unsetenv(folder_variable);
  for (const auto& [name, value] : variables)
    unsetenv(name.c_str());
  return o;
}

inline CliOutcome run_mpi(int n, const std::string& args, int timeout_s = 400,
                          const std::string& mpirun_options = "") {
  return run_mpi_program(n, std::string(magfem_binary()) + " " + args, timeout_s, mpirun_options);
}

inline nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

inline std::string text_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Largest |a - b| over the B columns of two probe tables, relative to the largest |B| there.
inline double probe_difference(const ProbeTable& a, const ProbeTable& b) {
  EXPECT_EQ(a.columns, b.columns);
  EXPECT_EQ(a.rows.size(), b.rows.size());
  double diff = 0, scale = 0;
  for (const char* c : {"Bx", "By", "Bz"}) {
    const std::size_t k = a.column(c);
    for (std::size_t i = 0; i < std::min(a.rows.size(), b.rows.size()); ++i) {
      diff = std::max(diff, std::abs(a.rows[i][k] - b.rows[i][k]));
      scale = std::max(scale, std::abs(a.rows[i][k]));
    }
  }
  return scale > 0 ? diff / scale : diff;
}

} // namespace magfem::test

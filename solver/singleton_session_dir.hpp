#pragma once
// Open MPI's session directory for a process started without mpirun (an MPI singleton).
//
// Every isolated singleton on a machine names its session directory the same
// (<tmp>/ompi.<host>.<uid>/jf.0/1), and each removes the shared parents when it finalizes: two
// magfem processes starting and finishing at once (a shell loop with &, ctest -j2, Python
// worker processes) make one fail in orte_init ("mkdir .../jf.0/1: No such file or
// directory"), about 1 start in 100 with 8 at once. A directory of the process's own under
// TMPDIR, given to Open MPI before MPI starts and removed after it ends, takes the sharing away.
#include <string>

namespace magfem::petsc_module {

class SingletonSessionDir {
public:
  // Creates the directory and points OMPI_MCA_orte_tmpdir_base at it, unless the process runs
  // under mpirun (whose daemon owns the session) or the user chose a directory already.
  SingletonSessionDir();
  ~SingletonSessionDir(); // removes the directory it created (call after MPI_Finalize)
  SingletonSessionDir(const SingletonSessionDir&) = delete;
  SingletonSessionDir& operator=(const SingletonSessionDir&) = delete;

  const std::string& path() const { return path_; } // "" when none was created

private:
  std::string path_;
};

} // namespace magfem::petsc_module

#include "solver/singleton_session_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

namespace magfem::petsc_module {

SingletonSessionDir::SingletonSessionDir() {
  if (std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("OMPI_MCA_orte_tmpdir_base"))
    return;
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/magfem-mpi-XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  // Without a directory of its own the process falls back to Open MPI's shared default,
  // which works unless another singleton races it: not worth failing the run for.
  if (!mkdtemp(name.data()))
    return;
  path_ = name.data();
  setenv("OMPI_MCA_orte_tmpdir_base", path_.c_str(), 1);
}

SingletonSessionDir::~SingletonSessionDir() {
  if (path_.empty())
    return;
  std::error_code ignored; // a leftover temporary directory is no reason to fail at exit
  std::filesystem::remove_all(path_, ignored);
}

} // namespace magfem::petsc_module

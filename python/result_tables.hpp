#pragma once
// What the Python solutions (solution.hpp, analytic.hpp) share: probe tables as numpy columns
// and summary.json taken from the command line's own writer.
#include <filesystem>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "postproc/probe_table.hpp"

namespace magfem::python {

// name -> {column: 1-D numpy array}, the CSV files' columns in full precision.
pybind11::dict probes_dict(const std::vector<ProbeTable>& probes);

// A temporary folder (mkdtemp), removed with its contents at the end of the scope.
class TempDir {
public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
};

std::string read_text(const std::filesystem::path& path);

// summary.json as `write_outputs(run, dir)` writes it. It is assembled inside the writer,
// between the files it stages, so it is taken from there (written into a temporary folder and
// read back) rather than rebuilt: the command line's byte for byte, and it cannot drift when
// fields are added to it. The VTU is switched off for that write (seconds on a big mesh, and
// not part of the summary) and put back at once; the caller keeps other writers away.
template <typename Run, typename Writer> std::string summary_via_outputs(Run& run, Writer write) {
  const TempDir dir;
  const bool vtu = run.spec.write_vtu;
  run.spec.write_vtu = false;
  try {
    write(run, dir.path());
  } catch (...) {
    run.spec.write_vtu = vtu;
    throw;
  }
  run.spec.write_vtu = vtu;
  return read_text(dir.path() / "summary.json");
}

} // namespace magfem::python

// magfem._core: the compiled part of the Python package (issue 32). It binds library calls,
// never the command line; python/magfem/__init__.py re-exports it.
#include <pybind11/pybind11.h>

namespace py = pybind11;

PYBIND11_MODULE(_core, m) {
  m.doc() = "Compiled part of the magfem package; use `import magfem`.";
  m.attr("__version__") = MAGFEM_VERSION;
}

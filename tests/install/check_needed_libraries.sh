#!/usr/bin/env bash
# Start-up (issue 35): the executable and the Python module must not list PETSc, MPI or VTK
# among the libraries the loader maps at start (DT_NEEDED); those live in the backend modules,
# opened when a command first needs them. The modules themselves must list them, which also
# shows that readelf read the files (an empty listing would pass the first check vacuously).
# Usage: check_needed_libraries.sh MODULE_DIR BINARY... (the executable, the Python module)
set -euo pipefail
modules=$1
shift
fail() { echo "FAIL: $*" >&2; exit 1; }
needed() { readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'; }
backend='^lib(petsc|mpi|vtk|HYPRE|hypre)'

for binary in "$@"; do
  list=$(needed "$binary")
  grep -q '^libc\.so' <<<"$list" || fail "readelf found no libc in $binary: $list"
  if grep -E "$backend" <<<"$list"; then
    fail "$binary loads the libraries above at start-up; only lib/magfem/libmagfem_{petsc,vtk}.so may"
  fi
  echo "$binary: $(wc -l <<<"$list") libraries, none of PETSc, MPI, VTK"
done
grep -q '^libpetsc' <<<"$(needed "$modules/libmagfem_petsc.so")" || fail "libmagfem_petsc.so lacks PETSc"
grep -q '^libmpi' <<<"$(needed "$modules/libmagfem_petsc.so")" || fail "libmagfem_petsc.so lacks MPI"
grep -q '^libvtk' <<<"$(needed "$modules/libmagfem_vtk.so")" || fail "libmagfem_vtk.so lacks VTK"
echo "PETSc and MPI in libmagfem_petsc.so, VTK in libmagfem_vtk.so: ok"

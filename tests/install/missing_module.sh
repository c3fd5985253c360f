#!/usr/bin/env bash
# An installation without its backend modules (issue 35): commands that need neither PETSc
# nor VTK still run (--version, an analytic sweep); a command that needs one stops with exit 1
# and a message naming the missing file, and leaves no outputs behind.
# Usage: missing_module.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
src=$2
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$root/prefix" >/dev/null
modules=$(dirname "$(find "$root/prefix" -name libmagfem_petsc.so)")
[[ -f $modules/libmagfem_vtk.so ]] || fail "the modules are not installed side by side"
rm "$modules"/libmagfem_petsc.so "$modules"/libmagfem_vtk.so
exe=$root/prefix/bin/magfem
cd "$root"

"$exe" --version >/dev/null || fail "--version needs a backend module"
"$exe" sweep "$src/examples/3d/compensator_table42.yaml" --rotate outer --axis y --angles 0:90:180 \
  --analytic --out sweep >/dev/null 2>&1 || fail "an analytic sweep needs a backend module"
[[ -f sweep/sweep.csv ]] || fail "the analytic sweep wrote no sweep.csv"

expect_missing() { # module out-dir command...
  local module=$1 out=$2 status=0
  shift 2
  "$@" --out "$out" >/dev/null 2>err.txt || status=$?
  ((status == 1)) || fail "$* exited $status without $module, expected 1: $(cat err.txt)"
  grep -q "installation error: cannot load $module" err.txt || fail "the message does not name $module: $(cat err.txt)"
  grep -q "looked in $modules" err.txt || fail "the message does not say where it looked: $(cat err.txt)"
  [[ ! -e $out/summary.json ]] || fail "$* left a summary.json without $module"
  echo "without $module: $(cat err.txt)"
}
# A 2D solve writes solution.vtu (VTK); PETSc options in a case are checked by PETSc itself.
expect_missing libmagfem_vtk.so solve2d "$exe" solve "$src/examples/2d/diametric_cylinder.yaml"
expect_missing libmagfem_petsc.so solve3d "$exe" solve "$src/examples/3d/magnetized_sphere_amg.yaml"

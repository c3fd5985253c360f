#!/usr/bin/env bash
# Installs the Debian 12 packages magfem needs (as root). Skips apt-get entirely when
# everything is already installed, so repeated runs are fast.
set -euo pipefail
# libopenblas0-pthread replaces the reference BLAS behind CHOLMOD's supernodal factorization
# (measured: nonlinear motor, 108k unknowns, 3.9 s -> 2.6 s); gnuplot-nox draws sweep plots;
# python3-jsonschema/python3-yaml check docs/case.schema.json against the examples; dpkg-dev
# and file let CPack compute the Debian package's runtime dependencies; libnlopt-cxx-dev is
# the bounded optimizer behind magfem optimize; libpetsc-real-dev (with hypre and Open MPI)
# gives the 3D solver algebraic multigrid, and mpi-default-bin its mpirun (libscotch-dev, which
# it brings, is named for the partition's fixed random seed); pybind11-dev and
# python3-numpy build the Python module (python/), python3-pytest runs its tests, python3-scipy
# the optimizer of examples/python/compensator_design.py and its test (skipped without it).
packages=(cmake g++ make ccache pkg-config
          libeigen3-dev libyaml-cpp-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev
          libsuitesparse-dev libtet1.5-dev libvtk9-dev nlohmann-json3-dev libtbb-dev
          libgtest-dev gnuplot-nox libopenblas0-pthread libnlopt-cxx-dev
          libpetsc-real-dev libscotch-dev mpi-default-bin
          python3-jsonschema python3-yaml dpkg-dev file
          pybind11-dev python3-numpy python3-pytest python3-scipy)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  SUDO=""
  [[ $(id -u) -eq 0 ]] || SUDO="sudo"
  $SUDO apt-get update -qq
  # --no-remove: never take away a package the user has. On Debian 12, libvtk9-dev and
  # ParaView's Python module (python3-paraview) conflict; apt then stops instead of removing one.
  if ! $SUDO apt-get install -y -qq --no-install-recommends --no-remove "${missing[@]}"; then
    echo "install_deps: apt-get could not install ${missing[*]} without removing packages." >&2
    echo "  A known case: python3-paraview conflicts with libvtk9-dev (see README, ParaView)." >&2
    echo "  Resolve the conflict by hand, then run this script again." >&2
    exit 1
  fi
fi

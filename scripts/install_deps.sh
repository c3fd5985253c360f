#!/usr/bin/env bash
# Installs the Debian 12 packages magfem needs (as root). Skips apt-get entirely when
# everything is already installed, so repeated runs are fast.
set -euo pipefail
# libopenblas0-pthread replaces the reference BLAS behind CHOLMOD's supernodal factorization
# (measured: nonlinear motor, 108k unknowns, 3.9 s -> 2.6 s); gnuplot-nox draws sweep plots.
packages=(cmake g++ make ccache pkg-config
          libeigen3-dev libyaml-cpp-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev
          libsuitesparse-dev libtet1.5-dev libvtk9-dev nlohmann-json3-dev libtbb-dev
          libgtest-dev gnuplot-nox libopenblas0-pthread)
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
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

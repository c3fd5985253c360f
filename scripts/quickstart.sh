#!/usr/bin/env bash
# Set-up + build + a real example end to end: the exact diametric cylinder, leaving
# out/cylinder/{summary.json,r12.csv,r5.csv,x_axis.csv,solution.vtu}.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
./build/magfem solve examples/2d/diametric_cylinder.yaml --out out/cylinder
ls -l out/cylinder

#!/usr/bin/env bash
# Builds the Debian package (CPack) from ./build and checks it: declared dependencies, then
# unpacks it into a temporary root (dpkg -x) and runs an example and --version from there.
# The .deb is left in build/.  Install it with: sudo apt install ./build/magfem_*.deb
set -euo pipefail
cd "$(dirname "$0")/.."
[[ -x build/magfem ]] || bash scripts/build.sh
(cd build && cpack -G DEB >/dev/null)
deb=$(ls -t build/magfem_*.deb | head -1)
echo "package: $deb ($(du -h "$deb" | cut -f1))"
dpkg-deb -f "$deb" Package Version Architecture Depends Recommends
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
dpkg -x "$deb" "$root"
"$root/usr/bin/magfem" --version
(cd "$root" && ./usr/bin/magfem solve usr/share/magfem/examples/2d/diametric_cylinder.yaml \
  --out "$root/out" >/dev/null)
grep -E '"(magfem_version|commit)"' "$root/out/summary.json"
echo "unpacked package runs: ok"

#!/usr/bin/env bash
# Installs the build into a temporary prefix, moves the prefix elsewhere (the installed tree
# must not depend on where it was installed, nor on the build tree), and runs from there:
# --version, help pages, a 2D example (summary.json carries version and commit) and one
# validation entry (the catalogue must come from the installed share/magfem). With PYTHON (the
# interpreter the module was built for): `import magfem` from the moved prefix with
# PYTHONPATH=<prefix>/lib/python3/dist-packages, a solve and a sweep through it, and a
# validation entry that must also find the installed catalogue.
# Usage: install_and_run.sh BUILD_DIR [PYTHON]
set -euo pipefail
build=$1
python=${2:-}
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$root/first" >/dev/null
mv "$root/first" "$root/moved"
prefix=$root/moved
exe=$prefix/bin/magfem
share=$prefix/share/magfem
for f in "$exe" "$share/examples/2d/diametric_cylinder.yaml" "$share/docs/case_format.md" \
  "$share/validation/catalogue.yaml" "$share/validation/cases/harwin_paper_model.yaml" \
  "$share/materials/library.yaml" "$prefix/share/bash-completion/completions/magfem"; do
  [[ -e $f ]] || fail "not installed: ${f#$prefix/}"
done

version=$("$exe" --version)
[[ $version =~ ^magfem\ ([0-9]+\.[0-9]+\.[0-9]+)\ \(commit\ ([0-9a-f]{40}(-dirty)?|unknown)\)$ ]] ||
  fail "--version printed '$version'"
semver=${BASH_REMATCH[1]}
commit=${BASH_REMATCH[2]}
echo "installed: $version"

"$exe" help solve | grep -q -- '--mesh-scale' || fail "help solve lacks --mesh-scale"
"$exe" validate --help | grep -q -- '--tier' || fail "validate --help lacks --tier"
status=0
"$exe" help nonsense >/dev/null 2>&1 || status=$?
((status == 2)) || fail "help for an unknown command exited $status, expected 2"

# Run from an unrelated directory so nothing can be found relative to the working directory.
work=$root/work
mkdir -p "$work"
cd "$work"
"$exe" solve "$share/examples/2d/diametric_cylinder.yaml" --out solve >/dev/null
summary=solve/summary.json
grep -q "\"magfem_version\": \"$semver\"" $summary || fail "summary.json lacks magfem_version $semver"
grep -q "\"commit\": \"$commit\"" $summary || fail "summary.json lacks commit $commit"

"$exe" validate --only harwin.t1.paper.max_ratio_4 --jobs 1 --out validate >/dev/null
grep -q "\"catalogue\": \"$share/validation/catalogue.yaml\"" validate/results.json ||
  fail "validate did not use the installed catalogue: $(grep catalogue validate/results.json)"
echo "install, relocation, solve and validate from the prefix: ok"

[[ -n $python ]] || exit 0
site=$prefix/lib/python3/dist-packages
[[ -f $site/magfem/__init__.py ]] || fail "not installed: lib/python3/dist-packages/magfem"
ls "$site"/magfem/_core.*.so >/dev/null 2>&1 || fail "not installed: the compiled magfem._core"
PYTHONPATH=$site "$python" - "$site" "$share" "$semver" <<'PY' || fail "the installed Python module"
import sys
import magfem
site, share, semver = sys.argv[1:]
assert magfem.__file__.startswith(site + "/"), "imported %s, not the installed one" % magfem.__file__
assert magfem.__version__ == semver, magfem.__version__
sol = magfem.Case.load(share + "/examples/2d/diametric_cylinder.yaml").solve(mesh_scale=2.0)
assert sol.summary["magfem_version"] == semver and sol.energy > 0
curve = magfem.sweep(magfem.Case.load(share + "/examples/3d/compensator_table42.yaml"),
                     rotate="outer", angles=[0, 90], analytic=True)
assert abs(curve["Ty"][1]) > 1, curve
v = magfem.validate(entries=["harwin.t1.paper.max_ratio_4"], jobs=1)
assert v.catalogue == share + "/validation/catalogue.yaml", "validate used " + v.catalogue
assert v.failed == [], v.rows
PY
echo "Python module from the prefix: import, solve, sweep and validate: ok"

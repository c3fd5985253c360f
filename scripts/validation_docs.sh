#!/usr/bin/env bash
# Regenerates docs/validation_quick.md: the quick tier of `magfem validate` (every analytic
# figure of the papers and the 2D FE ones), with the commit it ran on. The README links to it
# rather than carrying a copy that ages. Needs a build (bash scripts/build.sh); ~2 min on 2
# cores. Exit code: that of magfem validate (4 when an entry fails; the page is still written).
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
rc=0
build/magfem validate --tier quick --out "$out" > "$out/console.txt" 2>&1 || rc=$?
if [[ ! -s "$out/report.md" ]]; then
  cat "$out/console.txt" >&2
  echo "validation_docs: magfem validate wrote no report (exit $rc)" >&2
  exit $((rc == 0 ? 1 : rc))
fi
commit=$(git rev-parse --short=12 HEAD)
dirty=$(git diff --quiet HEAD -- . ':!docs' && echo "" || echo " (with uncommitted changes)")
{
  echo "# Validation, quick tier"
  echo
  echo "Produced by \`bash scripts/validation_docs.sh\` (\`magfem validate --tier quick\`) on commit"
  echo "$commit$dirty, $(date -u +%Y-%m-%d). Do not edit by hand. Seeds: 000 Harwin, 001 DMP,"
  echo "002 voice coil, 003 thesis (\`../shared/seeds/README.md\`); the full tier (\`--tier full\`,"
  echo "3D FE on publication meshes) runs in the long tier (\`bash scripts/test.sh --long\`)."
  echo
  # The report names the case files by the path it was given; keep them relative to the checkout.
  sed "s|$PWD/||g" "$out/report.md"
} > docs/validation_quick.md
echo "wrote docs/validation_quick.md (validate exit $rc)"
exit "$rc"

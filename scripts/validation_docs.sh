#!/usr/bin/env bash
# Regenerates docs/validation_quick.md: the quick tier of `magfem validate` (every analytic
# figure of the papers and the 2D FE ones), with the commit it ran on. The README links to it
# rather than carrying a copy that ages. Needs a build (bash scripts/build.sh); ~2 min on 2
# cores.
#   --full   the full tier instead (3D FE on publication meshes: ~25 min on 2 cores, up to
#            ~7 GB per job) into docs/validation_full.md: the record of when the tier last ran
#            whole, and on which commit (nothing in the default suite runs it).
# Exit code: that of magfem validate (4 when an entry fails; the page is still written).
set -euo pipefail
cd "$(dirname "$0")/.."
tier=quick
if [[ "${1:-}" == "--full" ]]; then
  tier=full
elif [[ $# -gt 0 ]]; then
  echo "usage: bash scripts/validation_docs.sh [--full]" >&2
  exit 2
fi
page="docs/validation_$tier.md"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# The checkout as the run starts (a long run outlives edits made beside it).
commit=$(git rev-parse --short=12 HEAD)
dirty=$(git diff --quiet HEAD -- . ':!docs' && echo "" || echo " (with uncommitted changes)")
rc=0
start=$(date +%s)
build/magfem validate --tier "$tier" --out "$out" > "$out/console.txt" 2>&1 || rc=$?
minutes=$(( ($(date +%s) - start + 30) / 60 ))
if [[ ! -s "$out/report.md" ]]; then
  cat "$out/console.txt" >&2
  echo "validation_docs: magfem validate wrote no report (exit $rc)" >&2
  exit $((rc == 0 ? 1 : rc))
fi
{
  echo "# Validation, $tier tier"
  echo
  flag=""
  [[ "$tier" == full ]] && flag=" --full"
  echo "Produced by \`bash scripts/validation_docs.sh$flag\` (\`magfem validate --tier $tier\`) on commit"
  echo "$commit$dirty, $(date -u +%Y-%m-%d), in about $minutes min on $(nproc) cores. Do not edit"
  echo "by hand. Seeds: 000 Harwin, 001 DMP, 002 voice coil, 003 thesis (\`../shared/seeds/README.md\`)."
  if [[ "$tier" == quick ]]; then
    echo "The full tier (3D FE on publication meshes): [validation_full.md](validation_full.md)."
  else
    echo "The quick tier: [validation_quick.md](validation_quick.md)."
  fi
  echo
  # The report names the case files by the path it was given; keep them relative to the checkout.
  sed "s|$PWD/||g" "$out/report.md"
} > "$page"
echo "wrote $page (validate exit $rc)"
exit "$rc"

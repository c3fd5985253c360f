#!/usr/bin/env bash
# Measures the accuracy that example files claim in their comments, against the exact or
# independent answer, and writes docs/example_accuracy.md with the commit it ran on. The
# claims in the examples quote this file; rerun it when the mesher or the solver changes.
#   bash scripts/example_accuracy.sh            (needs a build: bash scripts/build.sh)
#   MAGFEM=otherbuild/magfem bash scripts/example_accuracy.sh   (another build of this commit)
# About 6 min on 2 cores (the adaptive compensator: 3 passes to ~1.7 M unknowns, ~3 GB; TEAM 20
# at order 2: ~3 min, ~2 GB).
set -euo pipefail
cd "$(dirname "$0")/.."
magfem=${MAGFEM:-build/magfem}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
doc=docs/example_accuracy.md
commit=$(git rev-parse --short=12 HEAD)
dirty=$(git diff --quiet HEAD -- . ':!docs' && echo "" || echo " (with uncommitted changes)")

# sweep.csv columns: angle_deg,Tx,Ty,Tz,Fx,Fy,Fz. Prints a table row per angle and the largest
# difference of any torque and any force component as % of the analytic peak |T| and |F|.
compare_sweeps() { # fe.csv analytic.csv
  paste -d, "$1" "$2" | awk -F, '
    NR == 1 { next }
    { n++; a[n] = $1; for (k = 2; k <= 7; k++) { fe[n, k] = $k; an[n, k] = $(k + 7) }
      for (k = 2; k <= 4; k++) if ((v = ($(k + 7) < 0 ? -$(k + 7) : $(k + 7))) > pt) pt = v
      for (k = 5; k <= 7; k++) if ((v = ($(k + 7) < 0 ? -$(k + 7) : $(k + 7))) > pf) pf = v }
    END {
      print "| angle (deg) | T_y FE (N m) | T_y charge model (N m) | F FE (N) | F charge model (N) |"
      print "|---|---|---|---|---|"
      for (i = 1; i <= n; i++) {
        printf "| %g | %.4f | %.4f | (%.2f, %.2f, %.2f) | (%.2f, %.2f, %.2f) |\n", a[i], fe[i, 3],
          an[i, 3], fe[i, 5], fe[i, 6], fe[i, 7], an[i, 5], an[i, 6], an[i, 7]
        for (k = 2; k <= 4; k++) { d = fe[i, k] - an[i, k]; if (d < 0) d = -d; if (d > dt) dt = d }
        for (k = 5; k <= 7; k++) { d = fe[i, k] - an[i, k]; if (d < 0) d = -d; if (d > df) df = d }
      }
      printf "\nLargest difference: torque %.2f %% of the peak %.3f N m, force %.2f %% of the peak %.1f N.\n",
        100 * dt / pt, pt, 100 * df / pf, pf
    }'
}

{
  echo "# Example accuracy"
  echo
  echo "Produced by \`bash scripts/example_accuracy.sh\` on commit $commit$dirty, $(date -u +%Y-%m-%d)."
  echo "Do not edit by hand: the example files quote these figures."
  echo
  echo "## examples/3d/compensator_table42.yaml"
  echo
  echo "FE (\`magfem sweep --rotate outer --axis y --angles 0,60,90\`, the example's own mesh)"
  echo "against the charge model (\`--analytic\`, exact for these uniformly magnetized bodies)."
  echo
} > "$out/doc.md"

case=examples/3d/compensator_table42.yaml
start=$(date +%s)
$magfem sweep "$case" --rotate outer --axis y --angles 0,60,90 --out "$out/fe" > "$out/fe.log"
end=$(date +%s)
$magfem sweep "$case" --rotate outer --axis y --angles 0,60,90 --analytic --out "$out/an" > /dev/null
unknowns=$(grep -m1 '"unknowns"' "$out/fe/summary.json" | sed 's/.*: *//; s/,$//' || true)
compare_sweeps "$out/fe/sweep.csv" "$out/an/sweep.csv" >> "$out/doc.md"
echo >> "$out/doc.md"
echo "FE sweep: $((end - start)) s wall on $(nproc) cores${unknowns:+, $unknowns unknowns per position}." >> "$out/doc.md"

# The adaptive compensator at 90 deg: each pass's torque against the charge model, beside uniform
# --mesh-scale refinement of the same first mesh (the example's `scale: 3` times 1, 0.8, 0.65).
{
  echo
  echo "## examples/3d/compensator_adaptive.yaml"
  echo
  echo "The torque on the inner magnet at 90 deg against the charge model's exact -T_y of the"
  echo 'outer one (`magfem sweep compensator_table42.yaml --rotate outer --axis y --angles 90'
  echo '--analytic`); adaptive passes (`magfem solve`, the example as it is) and uniform'
  echo 'refinement of the same first mesh (its `adapt:` removed, `--mesh-scale` 1, 0.8, 0.65).'
  echo
} >> "$out/doc.md"
case=examples/3d/compensator_adaptive.yaml
$magfem sweep examples/3d/compensator_table42.yaml --rotate outer --axis y --angles 90 --analytic \
  --out "$out/an90" > /dev/null
exact=$(awk -F, 'NR == 2 { print $3 }' "$out/an90/sweep.csv")
start=$(date +%s)
$magfem solve "$case" --quiet --out "$out/adaptive" > /dev/null
end=$(date +%s)
sed '/^adapt:/,$d' "$case" > "$out/uniform.yaml"
for scale in 1 0.8 0.65; do
  $magfem solve "$out/uniform.yaml" --mesh-scale $scale --quiet --out "$out/uniform$scale" > /dev/null
done
python3 - "$exact" "$out" >> "$out/doc.md" <<'PY'
import json, sys
exact, out = float(sys.argv[1]), sys.argv[2]
def torque(summary):  # the inner magnet's T_y: minus the outer one's
    return -next(f for f in summary["forces"] if f["name"] == "inner")["torque_Nm"][1]
def row(kind, unknowns, t, estimated):
    est = "" if estimated is None else f"{estimated:.3g}"
    print(f"| {kind} | {unknowns:,} | {t:.4f} | {est} | {100 * abs(t - exact) / exact:.3g} |")
print("| run | unknowns | T_y (N m) | estimated error (%) | true error (%) |")
print("|---|---|---|---|---|")
adaptive = json.load(open(f"{out}/adaptive/summary.json"))
for p in adaptive["adapt"]["passes"]:
    # the named quantity is |T|; T is along -y here (uniform rows: T_y itself)
    row(f"adaptive pass {p['pass']}", p["unknowns"], p["quantities"]["forces.inner.torque"],
        p["quantity_error_pct"]["forces.inner.torque"])
for scale in ("1", "0.8", "0.65"):
    s = json.load(open(f"{out}/uniform{scale}/summary.json"))
    f = next(f for f in s["forces"] if f["name"] == "inner")
    est = f.get("error_estimate", {}).get("torque_Nm")
    t = torque(s)
    row(f"uniform --mesh-scale {scale}", s["unknowns"], t,
        None if est is None else 100 * (sum(e * e for e in est)) ** 0.5 / abs(t))
a = adaptive["adapt"]
print(f"\nAdaptive: converged {str(a['converged']).lower()}, peak memory "
      f"{adaptive['peak_memory_MB']:.0f} MB.")
PY
echo "Adaptive run: $((end - start)) s wall on $(nproc) cores." >> "$out/doc.md"

# TEAM 20 at 3000 AT on the example's own mesh (order 2) against the measurements its comment
# quotes (Kettunen et al. 1994, Table III; the same values are in tests/pipeline/test_team20.cpp).
{
  echo
  echo "## examples/3d/team20.yaml"
  echo
  echo 'TEAM Problem 20 at 3000 AT (`magfem solve`, the example as it is: order 2, its own mesh)'
  echo "against the measured force on the pole and flux density in the gap."
  echo
} >> "$out/doc.md"
start=$(date +%s)
$magfem solve examples/3d/team20.yaml --quiet --out "$out/team20" > /dev/null
end=$(date +%s)
python3 - "$out/team20" >> "$out/doc.md" <<'PY'
import csv, json, sys
run = sys.argv[1]
s = json.load(open(f"{run}/summary.json"))
points = list(csv.DictReader(open(f"{run}/points.csv")))
measured = {"F_z (N)": -54.4, "Bz(P1) (T)": 0.84, "Bz(P2) (T)": 0.63}
fe = {"F_z (N)": next(f for f in s["forces"] if f["name"] == "pole")["force_N"][2],
      "Bz(P1) (T)": float(points[0]["Bz"]), "Bz(P2) (T)": float(points[1]["Bz"])}
print("| quantity | FE | measured | difference (%) |")
print("|---|---|---|---|")
for name, m in measured.items():
    print(f"| {name} | {fe[name]:.4g} | {m:g} | {100 * (fe[name] - m) / m:+.1f} |")
print(f"\n{s['elements']:,} tetrahedra, {s['unknowns']:,} unknowns; {s['iterations']} Newton "
      f"iterations (converged {str(s['converged']).lower()}), {s['linear_iterations']} CG "
      f"iterations in all; peak memory {s['peak_memory_MB']:.0f} MB.")
PY
echo "TEAM 20 run: $((end - start)) s wall on $(nproc) cores." >> "$out/doc.md"

mv "$out/doc.md" "$doc"
cat "$doc"

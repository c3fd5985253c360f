#!/usr/bin/env bash
# The open speed targets of issues 33 and 35, measured and written to docs/target_timings.md
# with the commit, the machine and its load (so a figure in a note can be traced to a run):
#   benchmark32 at its default mesh, serial and under mpirun -n 2 (wall, CPU, peak memory per
#   process, stage times, pointwise accuracy against the charge model);
#   the magnetized sphere's r = 12 mm table (wall, pointwise accuracy against the exact field);
#   the compensator's 8-position FE sweep, --jobs 1 against mpirun -n 2 (and whether sweep.csv
#   is byte-identical), and --jobs 1 on one thread (the ceiling of that ratio on 2 cores).
# About 12 min on a quiet 2-core machine (B32_PAIRS=3, SWEEP_PAIRS=3). Run it on a quiet machine: the figures are wall times.
#   bash scripts/target_timings.sh                 build/magfem, writes docs/target_timings.md
#   MAGFEM=build2/magfem bash scripts/target_timings.sh   another build of the same commit
set -euo pipefail
cd "$(dirname "$0")/.."
magfem=${MAGFEM:-build/magfem}
doc=docs/target_timings.md
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

mpirun_2=(mpirun -n 2)
if [[ $EUID -eq 0 ]]; then # Open MPI as root: the option and the variables
  mpirun_2+=(--allow-run-as-root)
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

timing() { sed -n '/"timings_s"/,/}/p' "$1/summary.json" | grep "\"$2\"" | sed 's/.*: *//; s/,$//'; }
field() { grep -m1 "\"$2\"" "$1/summary.json" | sed 's/.*: *//; s/,$//'; }
load() { cut -d' ' -f1 /proc/loadavg; }
# GNU time's wall, user, sys and peak RSS of one process: "wall user sys rss_MB".
# Each timed run starts with the page cache's dirty pages written out: a run that follows one
# which wrote 280 MB of VTU found its own write taking 2.2 s instead of 1.1 s (measured: with
# sync before each, serial and mpirun -n 2 both 1.2 s).
settle() { sync; sleep 2; }
timed() { # file command...
  local f=$1
  shift
  settle
  /usr/bin/time -f "%e %U %S %M" -o "$f" "$@" > /dev/null 2>&1
}
rss_mb() { awk '{ printf "%.0f", $4 / 1024 }' "$1"; }

# The memory read bandwidth, before and after (GB/s on 1 and 2 threads): the solves stream
# their matrices from memory, and this host's speed drifts.
g++ -std=c++20 -O2 -o "$out/memory_bandwidth" scripts/memory_bandwidth.cpp -lpthread
bandwidth_before=$("$out/memory_bandwidth")

b32=examples/3d/benchmark32_parallel.yaml
load_before=$(load)
$magfem analytic $b32 --out "$out/b32_exact" > /dev/null
# Serial and mpirun -n 2 alternate B32_PAIRS times (the host drifts, see the sweep below); the
# first pair's stages, memory and accuracy are reported in full, every pair's wall times.
b32_pairs=${B32_PAIRS:-3}
for ((k = 1; k <= b32_pairs; ++k)); do
  timed "$out/serial.$k.time" $magfem solve $b32 --quiet --out "$out/b32_serial.$k"
  # One GNU time per process: each rank's own peak memory.
  settle
  OMP_NUM_THREADS=1 "${mpirun_2[@]}" sh -c '/usr/bin/time -f "%e %U %S %M" -o "$0.$OMPI_COMM_WORLD_RANK.time" "$@"' \
    "$out/rank.$k" $magfem solve $b32 --quiet --out "$out/b32_2ranks.$k" > /dev/null 2>&1 ||
    { echo "mpirun -n 2 benchmark32 failed" >&2; exit 1; }
done
ln -s b32_serial.1 "$out/b32_serial"
ln -s b32_2ranks.1 "$out/b32_2ranks"
cp "$out/serial.1.time" "$out/serial.time"
cp "$out/rank.1.0.time" "$out/rank.0.time"
cp "$out/rank.1.1.time" "$out/rank.1.time"
pointwise() { # exact fe: "lo..hi" of pointwise rms (%) over Bx, By, Bz
  $magfem compare "$1" "$2" | awk '$1 ~ /^B[xyz]$/ { v = $5; lo = (lo == "" || v < lo) ? v : lo;
    hi = (v > hi) ? v : hi } END { printf "%.3g..%.3g", lo, hi }'
}

# The magnetized sphere's r = 12 mm table (issue 35: 0.05 % rms in <= 15 s): uniform meshes
# of magnetized_sphere.yaml and the adaptive run of benchmark.sh's target (a) (the whole table
# named at 0.1 %), each against the exact field.
sphere=examples/3d/magnetized_sphere.yaml
$magfem analytic $sphere --out "$out/sphere_exact" > /dev/null
sphere_scales="1.4 1"
for scale in $sphere_scales; do
  timed "$out/sphere_$scale.time" $magfem solve $sphere --mesh-scale $scale --quiet --out "$out/sphere_$scale"
done
sed -e 's/theta: \[30, 60\], phi: \[0, 90\]/theta: [0, 180], phi: [0, 360]/' \
  -e 's/name: patch/name: r12/; s/probes.patch/probes.r12/' -e 's/accuracy_pct: 0.5/accuracy_pct: 0.1/' \
  -e 's/max_unknowns: 1.0e6/max_unknowns: 3.0e6/' examples/3d/magnetized_sphere_probe_adaptive.yaml \
  > "$out/sphere_r12.yaml"
timed "$out/sphere_adaptive.time" $magfem solve "$out/sphere_r12.yaml" --quiet --out "$out/sphere_adaptive"

sweep=(sweep examples/3d/compensator_table42.yaml --rotate outer --axis y --angles 0:12.857:90
  --mesh-scale 2 --quiet)
# The sweep's two runs alternate, SWEEP_PAIRS times: this host's speed drifts by up to 2x
# within minutes (the same binary's benchmark32 mesh stage 13 s at one hour, 75 s at another),
# so one pair can say 2x either way; the median of the pairs' ratios is the figure.
pairs=${SWEEP_PAIRS:-3}
for ((k = 1; k <= pairs; ++k)); do
  timed "$out/sweep_serial.$k.time" $magfem "${sweep[@]}" --jobs 1 --out "$out/sweep_serial.$k"
  # The same on one thread: what each of the two processes does per position, so that
  # 2 x (--jobs 1) / (one thread) is the ratio a perfect split of the positions would give.
  MAGFEM_THREADS=1 OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 timed "$out/sweep_one_thread.$k.time" \
    $magfem "${sweep[@]}" --jobs 1 --out "$out/sweep_one_thread.$k"
  settle
  t0=$(date +%s.%N)
  "${mpirun_2[@]}" $magfem "${sweep[@]}" --out "$out/sweep_2ranks.$k" > /dev/null 2>&1
  awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }' > "$out/sweep_2ranks.$k.wall"
done
load_after=$(load)
bandwidth_after=$("$out/memory_bandwidth")

stages() { # dir
  printf "mesh %.1f, assembly %.1f, pmg set-up %.1f, CG %.1f, post %.1f (total %.1f s)" \
    "$(timing "$1" mesh)" "$(timing "$1" assemble)" "$(timing "$1" linear_setup)" \
    "$(timing "$1" linear_solve)" "$(timing "$1" postprocess)" "$(timing "$1" total)"
}
read -r s_wall s_user s_sys s_rss < "$out/serial.time"
serial_mb=$(rss_mb "$out/serial.time")
{
  echo "# Open speed targets (issues 33 and 35)"
  echo
  echo "Written by \`scripts/target_timings.sh\` on commit \`$(git rev-parse --short HEAD)$(git diff --quiet HEAD -- . ':!docs' || echo -dirty)\`,"
  echo "$(date -u +%Y-%m-%d), $(nproc) cores, load average $load_before before and $load_after after."
  echo "Wall times: a loaded machine makes them longer."
  echo "Memory read bandwidth (scripts/memory_bandwidth.cpp, GB/s on 1 and 2 threads): $bandwidth_before before, $bandwidth_after after."
  echo
  echo "## benchmark32 at its default mesh (issue 35: <= 30 s end to end at pointwise rms <= 0.6 %)"
  echo
  echo "| run | wall (s) | user + sys CPU (s) | peak memory per process (MB) | unknowns | CG iterations |"
  echo "|---|---|---|---|---|---|"
  printf "| serial | %s | %s + %s | %s | %s | %s |\n" "$s_wall" "$s_user" "$s_sys" "$serial_mb" \
    "$(field "$out/b32_serial" unknowns)" "$(field "$out/b32_serial" linear_iterations)"
  r0="$out/rank.0.time" r1="$out/rank.1.time"
  printf "| mpirun -n 2 | %s | %s + %s, %s + %s | %s (%.2f of serial), %s (%.2f) | %s | %s |\n" \
    "$(cut -d' ' -f1 "$r0")" "$(cut -d' ' -f2 "$r0")" "$(cut -d' ' -f3 "$r0")" \
    "$(cut -d' ' -f2 "$r1")" "$(cut -d' ' -f3 "$r1")" \
    "$(rss_mb "$r0")" "$(awk -v a="$(rss_mb "$r0")" -v b="$serial_mb" 'BEGIN { print a / b }')" \
    "$(rss_mb "$r1")" "$(awk -v a="$(rss_mb "$r1")" -v b="$serial_mb" 'BEGIN { print a / b }')" \
    "$(field "$out/b32_2ranks" unknowns)" "$(field "$out/b32_2ranks" linear_iterations)"
  echo
  echo "Stages (summary.json): serial $(stages "$out/b32_serial"); mpirun -n 2 $(stages "$out/b32_2ranks")."
  echo "Pointwise rms on r56 against the charge model (Bx, By, Bz, %): serial"
  echo "$(pointwise "$out/b32_exact/r56.csv" "$out/b32_serial/r56.csv"), mpirun -n 2 $(pointwise "$out/b32_exact/r56.csv" "$out/b32_2ranks/r56.csv")."
  echo
  echo "Alternating pairs (issue 33: mpirun -n 2 no slower than serial; rank 0's wall time):"
  echo
  echo "| pair | serial (s) | mpirun -n 2 (s) | serial / mpirun |"
  echo "|---|---|---|---|"
  for ((k = 1; k <= b32_pairs; ++k)); do
    s_k=$(cut -d' ' -f1 "$out/serial.$k.time") m_k=$(cut -d' ' -f1 "$out/rank.$k.0.time")
    printf "| %d | %s | %s | %.3f |\n" "$k" "$s_k" "$m_k" "$(awk -v a="$s_k" -v b="$m_k" 'BEGIN { print a / b }')"
  done
  echo
  b32_median=$(for ((k = 1; k <= b32_pairs; ++k)); do
    awk -v a="$(cut -d' ' -f1 "$out/serial.$k.time")" -v b="$(cut -d' ' -f1 "$out/rank.$k.0.time")" \
      'BEGIN { print a / b }'
  done | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
  printf "Median serial / mpirun over %d pairs: %.3f (>= 1: mpirun no slower).\n" "$b32_pairs" "$b32_median"
  echo
  echo "## The magnetized sphere's r = 12 mm table (issue 35: 0.05 % rms in <= 15 s)"
  echo
  echo "Probes read the patch-recovered B (postproc/probes3d.hpp). Pointwise rms against the exact"
  echo "field over the 703 points, range over Bx, By, Bz."
  echo
  echo "| run | unknowns | wall (s) | pointwise rms (%) |"
  echo "|---|---|---|---|"
  for scale in $sphere_scales; do
    printf "| uniform, --mesh-scale %s | %s | %s | %s |\n" "$scale" "$(field "$out/sphere_$scale" unknowns)" \
      "$(cut -d' ' -f1 "$out/sphere_$scale.time")" \
      "$(pointwise "$out/sphere_exact/r12.csv" "$out/sphere_$scale/r12.csv")"
  done
  printf "| adaptive, table named at 0.1 %% (%s passes) | %s | %s | %s |\n" \
    "$(grep -c '"pass":' "$out/sphere_adaptive/summary.json")" "$(field "$out/sphere_adaptive" unknowns)" \
    "$(cut -d' ' -f1 "$out/sphere_adaptive.time")" \
    "$(pointwise "$out/sphere_exact/r12.csv" "$out/sphere_adaptive/r12.csv")"
  echo
  echo "## The compensator's FE sweep, 8 positions (issue 33: mpirun -n 2 >= 1.7x the --jobs 1 run)"
  echo
  echo "| pair | --jobs 1 (s) | mpirun -n 2 (s) | ratio | one thread (s) | perfect split: 2 x --jobs 1 / one thread | sweep.csv |"
  echo "|---|---|---|---|---|---|---|"
  for ((k = 1; k <= pairs; ++k)); do
    read -r w_wall _ < "$out/sweep_serial.$k.time"
    w_2=$(cat "$out/sweep_2ranks.$k.wall")
    same=$(cmp -s "$out/sweep_serial.1/sweep.csv" "$out/sweep_2ranks.$k/sweep.csv" &&
      cmp -s "$out/sweep_serial.1/sweep.csv" "$out/sweep_serial.$k/sweep.csv" && echo identical ||
      echo DIFFERENT)
    read -r w_one _ < "$out/sweep_one_thread.$k.time"
    printf "| %d | %s | %s | %.2f | %s | %.2f | %s |\n" "$k" "$w_wall" "$w_2" \
      "$(awk -v a="$w_wall" -v b="$w_2" 'BEGIN { print a / b }')" "$w_one" \
      "$(awk -v a="$w_wall" -v b="$w_one" 'BEGIN { print 2 * a / b }')" "$same"
  done
  echo
  median=$(for ((k = 1; k <= pairs; ++k)); do
    awk -v a="$(cut -d' ' -f1 "$out/sweep_serial.$k.time")" -v b="$(cat "$out/sweep_2ranks.$k.wall")" \
      'BEGIN { print a / b }'
  done | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
  printf "Median ratio over %d pairs: %.2fx (sweep.csv: every run against the first --jobs 1 run).\n" \
    "$pairs" "$median"
  echo
  echo "Two processes on two cores each solve positions on one thread; against a serial run whose"
  echo "positions use both cores, a perfect split of the one-thread work gives 2 x (--jobs 1) /"
  echo "(one thread): the ceiling of the ratio, up to the timing noise, set by the serial run's"
  echo "own single-threaded parts. The 1.7x target needs that ceiling above 1.7, i.e. the serial"
  echo "run's two threads at most 1.18x faster than one."
} > "$doc"
cat "$doc"

"""Call overhead of magfem.Case.solve against a `magfem solve` process (issue 32 target:
<= 5 ms beyond the solve itself on a 2D case). Printed, not asserted, like benchmark.sh.
  PYTHONPATH=build/python /usr/bin/python3 scripts/benchmark_python.py [repeats]
Overhead = wall time of the call (or the process) minus the pipeline's own total in
summary.json (mesh, assembly, solve, post-processing)."""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import magfem

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
EXE = os.path.join(ROOT, "build", "magfem")
REPEATS = int(sys.argv[1]) if len(sys.argv) > 1 else 5


def median_ms(values):
    return 1e3 * statistics.median(values)


def python_overhead(case, **kw):
    over, wall = [], []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        sol = case.solve(**kw)
        t = time.perf_counter() - t0
        wall.append(t)
        over.append(t - sol.summary["timings_s"]["total"])  # summary read after the clock
    return median_ms(wall), median_ms(over), sol


def cli_overhead(path, out):
    over, wall = [], []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        subprocess.run([EXE, "solve", path, "--quiet", "--out", out], check=True,
                       stdout=subprocess.DEVNULL)
        t = time.perf_counter() - t0
        wall.append(t)
        with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
            over.append(t - json.load(f)["timings_s"]["total"])
    return median_ms(wall), median_ms(over)


def main():
    print("%-34s %12s %14s %12s %14s" % ("case", "python ms", "py overhead", "cli ms",
                                           "cli overhead"))
    with tempfile.TemporaryDirectory() as out:
        for name in ("axi/solenoid.yaml", "2d/diametric_cylinder.yaml"):
            path = os.path.join(ROOT, "examples", name)
            case = magfem.Case.load(path)
            py_wall, py_over, sol = python_overhead(case)
            cli_wall, cli_over = cli_overhead(path, out)
            print("%-34s %12.1f %14.2f %12.1f %14.1f" % (name, py_wall, py_over, cli_wall,
                                                           cli_over))
        # solve + write(dir): what the process does, without its start-up
        t0 = time.perf_counter()
        sol.write(os.path.join(out, "py"))
        print("write(dir) of the last case (VTU included): %.1f ms"
              % (1e3 * (time.perf_counter() - t0)))
        pts = np.random.default_rng(1).uniform(-0.02, 0.02, (100000, 3))
        t0 = time.perf_counter()
        sol.B(pts, outside="nan")
        print("B at 1e5 points: %.1f ms" % (1e3 * (time.perf_counter() - t0)))


if __name__ == "__main__":
    main()

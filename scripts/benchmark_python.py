"""Issue 32's speed targets, printed, not asserted, like benchmark.sh:
- call overhead of magfem.Case.solve against a `magfem solve` process (<= 5 ms beyond the
  solve itself on a 2D case); overhead = wall time of the call (or the process) minus the
  pipeline's own total in summary.json (mesh, assembly, solve, post-processing);
- the analytic 19-angle torque curve of the Table 4.2 compensator through magfem.sweep
  (<= 0.1 s, no process start-up), against a `magfem sweep --analytic` process;
- magfem.optimize of the docs' compensator problem (docs/performance.md) and the SLSQP design
  of examples/python/compensator_design.py (when scipy is installed).
  PYTHONPATH=build/python /usr/bin/python3 scripts/benchmark_python.py [repeats]"""
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
    over, wall, sol = [], [], None
    for _ in range(REPEATS):
        sol = None  # freeing the previous solution (its mesh and field) is not the call's
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


def timed_ms(call, repeats=REPEATS):
    """(first call, median of the repeats after it) in ms."""
    times = []
    for _ in range(repeats + 1):
        t0 = time.perf_counter()
        call()
        times.append(time.perf_counter() - t0)
    return 1e3 * times[0], median_ms(times[1:])


def studies(out):
    """The analytic compensator curve, an optimization and the SLSQP design."""
    table42 = os.path.join(ROOT, "examples", "3d", "compensator_table42.yaml")
    case = magfem.Case.load(table42)
    first, median = timed_ms(lambda: magfem.sweep(case, rotate="outer", axis="y",
                                                  angles=np.arange(0, 181, 10), analytic=True))
    t0 = time.perf_counter()
    subprocess.run([EXE, "sweep", table42, "--rotate", "outer", "--axis", "y", "--angles",
                    "0:10:180", "--analytic", "--out", out], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    cli = 1e3 * (time.perf_counter() - t0)
    print("analytic 19-angle compensator curve, magfem.sweep: %.1f ms median (first call "
          "%.1f ms); `magfem sweep --analytic` process: %.0f ms" % (median, first, cli))
    study = magfem.Case.load(os.path.join(ROOT, "examples", "3d", "compensator_study.yaml"))
    result = []
    first, median = timed_ms(lambda: result.append(magfem.optimize(
        study, vary={"R_in": (25, 40), "R_out": (45, 65)}, constraints="R_out - R_in <= 15",
        maximize="peak_torque", rotate="outer", axis="y", angles=[90])))
    print("magfem.optimize, compensator (2 variables, 1 constraint, %d evaluations): %.1f ms "
          "median" % (result[-1].evaluations, median))
    try:
        import scipy.optimize  # noqa: F401
    except ImportError:
        print("compensator_design.py: scipy not installed (python3-scipy), not timed")
        return
    sys.path.insert(0, os.path.join(ROOT, "examples", "python"))
    import compensator_design
    d = compensator_design.design(study)
    print("compensator_design.py SLSQP elbow design: R_out %.3f mm, %d torque curves in %.0f ms"
          % (d["R_out_mm"], d["evaluations"], 1e3 * d["seconds"]))


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
        studies(out)


if __name__ == "__main__":
    main()

"""Torque against tilt of the thesis's Table 4.2 gravity compensator
(examples/3d/compensator_table42.yaml) with magfem.sweep: the analytic curve at 19 angles in
milliseconds, then (with --fe) a few angles by finite elements on a coarse mesh beside it.
The result is a dict of numpy columns named as the command line's sweep.csv.

  PYTHONPATH=build/python /usr/bin/python3 examples/python/compensator_sweep.py
      [--fe 30,90] [--mesh-scale 2] [--checkpoint DIR] [--plot torque.png]

With --checkpoint DIR the FE angles are kept in DIR as they finish: after Ctrl-C, the same
command continues where it stopped (magfem.sweep's checkpoint_dir= and resume=True).
"""
import argparse
import os
import time

import numpy as np

import magfem

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "..", "3d", "compensator_table42.yaml")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--fe", help="angles (deg, comma-separated) to check by FE")
    parser.add_argument("--mesh-scale", type=float, default=2.0, help="FE mesh coarseness")
    parser.add_argument("--checkpoint", help="keep finished FE angles in this directory and "
                        "continue from what it holds")
    parser.add_argument("--plot", help="write a PNG of the curve (needs matplotlib)")
    args = parser.parse_args()

    case = magfem.Case.load(CASE)
    t0 = time.perf_counter()
    curve = magfem.sweep(case, rotate="outer", axis="y", angles=np.arange(0, 181, 10),
                         analytic=True)
    print("analytic (%s): %d angles in %.3f s" % (curve.method, len(curve["angle_deg"]),
                                                  time.perf_counter() - t0))
    for angle, ty in zip(curve["angle_deg"], curve["Ty"]):
        print("%8.1f deg  Ty = %9.4f N m" % (angle, ty))
    peak = np.argmax(np.abs(curve["Ty"]))
    print("peak |Ty| %.4f N m at %.0f deg" % (abs(curve["Ty"][peak]), curve["angle_deg"][peak]))

    fe = None
    if args.fe:
        angles = [float(a) for a in args.fe.split(",")]
        t0 = time.perf_counter()
        fe = magfem.sweep(case, rotate="outer", axis="y", angles=angles,
                          mesh_scale=args.mesh_scale, progress=True,
                          checkpoint_dir=args.checkpoint, resume=args.checkpoint is not None)
        print("FE (Maxwell stress on a sphere in the gap), %.1f s:" % (time.perf_counter() - t0))
        for angle, ty in zip(fe["angle_deg"], fe["Ty"]):
            exact = np.interp(angle, curve["angle_deg"], curve["Ty"])
            print("%8.1f deg  Ty = %9.4f N m  (analytic %9.4f)" % (angle, ty, exact))
    if args.plot:
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            print("matplotlib is not installed (python3-matplotlib): no plot")
            return
        plt.plot(curve["angle_deg"], curve["Ty"], label="analytic")
        if fe is not None:
            plt.plot(fe["angle_deg"], fe["Ty"], "o", label="FE")
        plt.xlabel("tilt of the outer shell about y (deg)")
        plt.ylabel("torque Ty (N m)")
        plt.legend()
        plt.savefig(args.plot, dpi=120)
        print("wrote", args.plot)


if __name__ == "__main__":
    main()

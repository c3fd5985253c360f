"""Torque against rotor angle of the RE25-like motor (examples/2d/re25_motor_torque.yaml),
solved in-process at a few angles, printed as a table (and plotted when matplotlib is there).

The rotor magnet is a diametrically magnetized disk, so turning the rotor by theta is the
same as turning its magnetization by theta: the script edits the case as a dict
(regions[0].magnetization.angle) instead of writing YAML files, and solves each angle with
Case.solve. Three independent torques come back per angle (the stress tensor on a circle
around the magnet, Arkkio's band average, and minus the Lorentz torque on the winding); they
should agree, and follow T(theta) = T(0) cos(theta) for this slotless motor.

  PYTHONPATH=build/python /usr/bin/python3 examples/python/torque_curve.py [--mesh-scale 2]
      [--plot torque.png]
"""
import argparse
import os
import time

import numpy as np
import yaml  # python3-yaml

import magfem

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "..", "2d", "re25_motor_torque.yaml")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mesh-scale", type=float, default=2.0,
                        help="coarser (> 1) or finer (< 1) than the case's mesh")
    parser.add_argument("--angles", default="0:30:180", help="start:step:end in degrees")
    parser.add_argument("--plot", help="write a PNG of the curve (needs matplotlib)")
    args = parser.parse_args()
    start, step, end = (float(x) for x in args.angles.split(":"))
    angles = np.arange(start, end + step / 2, step)

    with open(CASE, encoding="utf-8") as f:
        case = yaml.safe_load(f)
    case["stack_length"] = 25  # the 25 mm motor: forces in N, torques in N m
    rows = []
    print("%9s %12s %12s %12s %8s" % ("angle_deg", "T_stress", "T_arkkio", "-T_lorentz", "s"))
    for angle in angles:
        case["regions"][0]["magnetization"]["angle"] = float(angle)
        t0 = time.perf_counter()
        sol = magfem.Case.from_dict(case).solve(mesh_scale=args.mesh_scale)
        f = sol.forces
        row = (angle, f["rotor"]["torque_Nm"][2], f["rotor_band"]["torque_Nm"][2],
               -f["winding"]["torque_Nm"][2])
        rows.append(row)
        print("%9.1f %12.6f %12.6f %12.6f %8.2f" % (*row, time.perf_counter() - t0))

    rows = np.array(rows)
    fit = rows[0, 1] * np.cos(np.deg2rad(rows[:, 0]))
    print("largest departure of the stress torque from T(0) cos(angle): %.2e N m"
          % np.abs(rows[:, 1] - fit).max())
    if args.plot:
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            print("matplotlib is not installed (python3-matplotlib): no plot")
            return
        for k, label in enumerate(("stress tensor", "Arkkio band", "-Lorentz on winding")):
            plt.plot(rows[:, 0], rows[:, k + 1], marker="o", label=label)
        plt.xlabel("rotor angle (deg)")
        plt.ylabel("torque on the rotor (N m)")
        plt.legend()
        plt.savefig(args.plot, dpi=120)
        print("wrote", args.plot)


if __name__ == "__main__":
    main()

"""Designing the spherical gravity compensator for an elbow (thesis sec. 4.4.1) with
scipy.optimize over magfem's analytic model, then a finite-element check of the optimum.

The design question: the Table 4.2 compensator (inner hemisphere R_in 29 mm, outer shell to
R_out 43 mm, 1 mm gap, B_r 1.3 T) gives a peak torque T_42 of about 12.4 N m; an elbow needs
1.58 T_42. With the inner radius fixed at 35 mm, what is the least outer magnet that gives it?
The thesis answers R_out = 49.6 mm.

Each evaluation is the torque curve of the outer shell tilted about y, 0..180 deg in 10 deg
steps, by the analytic harmonic form of examples/3d/compensator_study.yaml through
magfem.sweep (milliseconds, no process, no file); the peak torque is the largest |Ty| on it,
as `magfem study --objective peak_torque` takes it. scipy.optimize.minimize (SLSQP) then
minimizes the outer shell's magnet volume under the constraint peak torque >= 1.58 T_42: the
optimum sits on the constraint, the elbow design. Last, the optimum is meshed and solved
(Maxwell stress on a sphere in the gap) at the peak angle and compared with the analytic
torque.

  PYTHONPATH=build/python /usr/bin/python3 examples/python/compensator_design.py
      [--r-in 35] [--factor 1.58] [--mesh-scale 1] [--no-fe]

Needs scipy (Debian: python3-scipy); without it the script says so and exits 0.
"""
import argparse
import math
import os
import sys
import time

import numpy as np

import magfem

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "..", "3d", "compensator_study.yaml")
ANGLES_DEG = np.arange(0, 181, 10)  # the torque curve of Fig. 4.9, as the command line's study
TABLE42 = {"R_in": 29.0, "R_out": 43.0}  # the thesis's Table 4.2 design, mm


def torque_curve(case, analytic=True, angles=ANGLES_DEG, mesh_scale=1.0):
    """Ty (N m) of the case's inner magnet as the outer shell tilts about y, one per angle."""
    return magfem.sweep(case, rotate="outer", axis="y", angles=angles, analytic=analytic,
                        mesh_scale=mesh_scale)


def peak_torque(case, **radii_mm):
    """The largest |Ty| (N m) on the analytic curve of the case with the given radii (mm)."""
    return float(np.abs(torque_curve(case.with_params(**radii_mm))["Ty"]).max())


def shell_volume_mm3(r_in, r_out, gap):
    """Magnet volume of the outer hemispherical shell (mm^3): what the design minimizes."""
    return 2.0 / 3.0 * math.pi * (r_out ** 3 - (r_in + gap) ** 3)


def design(case, r_in=35.0, factor=1.58):
    """The least outer radius (mm) at inner radius r_in whose peak torque is `factor` times the
    Table 4.2 design's, by SLSQP over the analytic model. Returns a dict: R_out_mm, torque_Nm,
    target_Nm, table42_Nm, evaluations, seconds. Raises ImportError without scipy and
    RuntimeError if the optimizer fails."""
    from scipy.optimize import minimize  # python3-scipy

    gap = case.parameters["gap"]
    t0 = time.perf_counter()
    table42 = peak_torque(case, **TABLE42)
    target = factor * table42
    evaluations = 0

    def torque_margin(x):
        nonlocal evaluations
        evaluations += 1
        # Scaled by the target so that SLSQP's tolerances mean the same for any design.
        return peak_torque(case, R_in=r_in, R_out=float(x[0])) / target - 1.0

    # From a generous shell (2 * R_in) down onto the constraint; the lower bound keeps a shell
    # at least 1 mm thick, which the case reader would otherwise refuse.
    start = 2.0 * r_in
    result = minimize(lambda x: shell_volume_mm3(r_in, x[0], gap) / shell_volume_mm3(r_in, start, gap),
                      x0=[start], method="SLSQP", bounds=[(r_in + gap + 1.0, 3.0 * r_in)],
                      constraints=[{"type": "ineq", "fun": torque_margin}],
                      options={"ftol": 1e-10, "maxiter": 100})
    if not result.success:
        raise RuntimeError("SLSQP did not converge: " + result.message)
    r_out = float(result.x[0])
    return {"R_out_mm": r_out, "torque_Nm": peak_torque(case, R_in=r_in, R_out=r_out),
            "target_Nm": target, "table42_Nm": table42, "evaluations": evaluations,
            "seconds": time.perf_counter() - t0}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--r-in", type=float, default=35.0, help="inner radius, mm")
    parser.add_argument("--factor", type=float, default=1.58, help="torque over Table 4.2's")
    parser.add_argument("--mesh-scale", type=float, default=1.0, help="FE mesh coarseness")
    parser.add_argument("--no-fe", action="store_true", help="skip the FE check")
    args = parser.parse_args()

    try:
        import scipy.optimize  # noqa: F401
    except ImportError:
        print("scipy is not installed (Debian: apt install python3-scipy): nothing to optimize")
        return 0

    case = magfem.Case.load(CASE)
    d = design(case, args.r_in, args.factor)
    print("Table 4.2 design (R_in %.0f, R_out %.0f mm): peak torque %.4f N m"
          % (TABLE42["R_in"], TABLE42["R_out"], d["table42_Nm"]))
    print("target %.2f x: %.4f N m" % (args.factor, d["target_Nm"]))
    print("SLSQP: R_out %.3f mm at R_in %.1f mm (thesis, R_in 35 mm and 1.58 x: 49.6 mm), "
          "peak torque %.4f N m; %d torque curves in %.3f s"
          % (d["R_out_mm"], args.r_in, d["torque_Nm"], d["evaluations"], d["seconds"]))
    if args.no_fe:
        return 0

    # The FE check at the analytic curve's peak angle (90 deg for these shells).
    optimum = case.with_params(R_in=args.r_in, R_out=d["R_out_mm"])
    curve = torque_curve(optimum)
    peak_deg = float(curve["angle_deg"][np.argmax(np.abs(curve["Ty"]))])
    t0 = time.perf_counter()
    fe = torque_curve(optimum, analytic=False, angles=[peak_deg], mesh_scale=args.mesh_scale)
    fe_torque = abs(float(fe["Ty"][0]))
    print("FE (%s, mesh scale %g) at %.0f deg: %.4f N m, %+.2f %% from the analytic %.4f N m "
          "(%.1f s)" % (fe.method, args.mesh_scale, peak_deg, fe_torque,
                        100 * (fe_torque / d["torque_Nm"] - 1), d["torque_Nm"],
                        time.perf_counter() - t0))
    return 0


if __name__ == "__main__":
    sys.exit(main())

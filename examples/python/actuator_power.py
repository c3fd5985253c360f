"""Copper loss of the thesis's spherical actuator (examples/3d/spherical_actuator_design.yaml)
over rotor orientations, with magfem.actuator: the torque constants Gamma (orientations x 3
x coils, N m/A) and the minimum-loss currents for 1 N m about x, y and z (thesis eq. 5.4),
as numpy arrays. Then, as a cross-check that needs no solve, the currents are recombined
for a demanded torque: the commutation is linear in the demand. With --coil-pitch, the
thesis's coil-pitch study (sec. 5.3) over the same orientations with magfem.coil_pitch: the
case's coils replaced by the thesis's array at each pitch, the mean loss per pitch (the
rotor's field is tabulated first: half a minute on a loaded 2-core machine).

  PYTHONPATH=build/python /usr/bin/python3 examples/python/actuator_power.py
      [--orientations rx=-30:15:30,ry=0:15:30,rz=0] [--coil-pitch 40:5:70]
"""
import argparse
import os
import time

import numpy as np

import magfem

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "..", "3d", "spherical_actuator_design.yaml")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--orientations", default="rx=0:30:30,ry=0:30:30,rz=0",
                        help="the command line's --orientations (degrees)")
    parser.add_argument("--coil-pitch", help="also the coil-pitch study over these pitches "
                        "(START:STEP:END or a comma list, degrees)")
    args = parser.parse_args()

    t0 = time.perf_counter()
    r = magfem.actuator(magfem.Case.load(CASE), rotor="rotor", orientations=args.orientations)
    print("%s: %d orientations x %d coils in %.2f s (%s)" % (
        r.method, len(r.orientations_deg), len(r.coils), time.perf_counter() - t0,
        ", ".join(r.notes) or "no notes"))
    print("%6s %6s %6s %9s %9s %9s %10s" % ("rx", "ry", "rz", "P_x W", "P_y W", "P_z W",
                                             "cond(G)"))
    p = r.commutations
    for i, (rx, ry, rz) in enumerate(r.orientations_deg):
        print("%6.1f %6.1f %6.1f %9.3f %9.3f %9.3f %10.3g" % (
            rx, ry, rz, p["P_x"]["P_W"][i], p["P_y"]["P_W"][i], p["P_z"]["P_W"][i],
            p["P_x"]["cond_Gamma"][i]))

    # 0.3 N m about x and 0.1 N m about z: the unit-torque currents combined, checked
    # against Gamma (the torque they make, N m).
    demand = np.array([0.3, 0.0, 0.1])
    currents = sum(demand[a] * p[name]["currents_A"] for a, name in enumerate(("P_x", "P_y",
                                                                              "P_z")))
    made = np.einsum("nak,nk->na", r.gamma, currents)
    print("T_d = %s N m: largest torque error of the recombined currents %.1e N m" % (
        demand, np.abs(made - demand).max()))

    if args.coil_pitch:
        t0 = time.perf_counter()
        study = magfem.coil_pitch(magfem.Case.load(CASE), rotor="rotor",
                                  orientations=args.orientations, pitches=args.coil_pitch)
        print("coil pitch (%.1f s): mean copper loss at 1 N m about x, y, z" % (
            time.perf_counter() - t0))
        print("%9s %7s %9s %9s %9s %9s" % ("pitch deg", "coils", "P_x W", "P_y W", "P_z W",
                                            "P_mean W"))
        for row in zip(*(study[c] for c in ("coil_pitch_deg", "n_coils", "P_x_W", "P_y_W",
                                            "P_z_W", "P_mean_W"))):
            print("%9.1f %7d %9.3f %9.3f %9.3f %9.3f" % row)
        print("least mean loss %.3f W at %g deg" % (study.minimum["P_mean_W"],
                                                   study.minimum["coil_pitch_deg"]))


if __name__ == "__main__":
    main()

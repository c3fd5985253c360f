"""magfem from Python in a dozen lines: load a case, solve it in-process, read the field on a
line and the coil's inductance, write the command line's outputs, plot when matplotlib is
there.

  PYTHONPATH=build/python /usr/bin/python3 examples/python/quickstart.py [--plot bore.png]
"""
import argparse
import os
import tempfile

import numpy as np

import magfem

HERE = os.path.dirname(os.path.abspath(__file__))

parser = argparse.ArgumentParser(description="solve the axisymmetric solenoid example")
parser.add_argument("--plot", help="write a PNG of Bz along the axis (needs matplotlib)")
args = parser.parse_args()

# An axisymmetric solenoid (examples/axi/solenoid.yaml), read by the same reader as
# `magfem solve`: a bad key raises magfem.InputError naming the field.
case = magfem.Case.load(os.path.join(HERE, "..", "axi", "solenoid.yaml"))
sol = case.solve(progress=lambda kind, text: kind == "stage" and print("  ..", text))
print(sol, "-", sol.summary["unknowns"], "unknowns")

# B at points: Cartesian x, y, z (here in mm), about the z axis for an axisymmetric case.
z = np.linspace(-30, 30, 7)
line = np.column_stack([np.zeros_like(z), np.zeros_like(z), z])
for zi, b in zip(z, sol.B(line, unit="mm")):
    print("  z = %6.1f mm   Bz = %.6f T" % (zi, b[2]))

winding = sol.coils["winding"]
print("winding: flux linkage %.4g Wb, L = %.4g H" % (winding["flux_linkage_Wb"],
                                                      winding["inductance_H"]))

with tempfile.TemporaryDirectory() as out:  # exactly `magfem solve --out`
    print("write() ->", sol.write(out))

if args.plot:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed (python3-matplotlib): no plot")
    else:
        z = np.linspace(-30, 30, 301)
        bz = sol.B(np.column_stack([0 * z, 0 * z, z]), unit="mm")[:, 2]
        plt.plot(z, bz)
        plt.xlabel("z (mm)")
        plt.ylabel("Bz on the axis (T)")
        plt.savefig(args.plot, dpi=120)
        print("wrote", args.plot)

"""The gravity compensator's design study (thesis ch. 4, Fig. 4.10; examples/3d/
compensator_study.yaml) with magfem.study: the peak torque over a grid of outer and inner
radii by the analytic harmonic form (milliseconds a design), and the first outer radius where
one more mm of magnet gains less than 2 % of peak torque (the curve's flattening).

  PYTHONPATH=build/python /usr/bin/python3 examples/python/compensator_study.py
      [--r-out 40:1:70] [--r-in 30,35]
"""
import argparse
import os
import time

import numpy as np

import magfem

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "..", "3d", "compensator_study.yaml")


def values(text):
    """START:STEP:END (END included) or A,B,C, as the command line's --param."""
    if ":" in text:
        start, step, end = (float(v) for v in text.split(":"))
        return np.arange(start, end + step / 2, step)
    return np.array([float(v) for v in text.split(",")])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--r-out", default="40:1:70", help="outer radii, mm")
    parser.add_argument("--r-in", default="35", help="inner radii, mm")
    args = parser.parse_args()

    t0 = time.perf_counter()
    result = magfem.study(magfem.Case.load(CASE),
                          params={"R_in": values(args.r_in), "R_out": values(args.r_out)},
                          objectives="peak_torque", rotate="outer", axis="y",
                          angles=np.arange(0, 181, 10))
    print("%s: %d designs in %.3f s, %d failed" % (result.method, result.summary["designs"],
                                                   time.perf_counter() - t0, result.failed))
    for r_in in np.unique(result["R_in"]):
        mine = result["R_in"] == r_in
        r_out, peak = result["R_out"][mine], result["peak_torque_Nm"][mine]
        gain = np.diff(peak) / peak[:-1] / np.diff(r_out)
        flat = np.nonzero(gain < 0.02)[0]
        elbow = "R_out %.0f mm" % r_out[flat[0]] if flat.size else "not within the grid"
        print("R_in %4.1f mm: peak torque %.2f .. %.2f N m; gain < 2 %%/mm from %s"
              % (r_in, peak[0], peak[-1], elbow))


if __name__ == "__main__":
    main()

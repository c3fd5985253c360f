"""The issue's design test (issue 32): a scipy.optimize loop over magfem's analytic
compensator (examples/python/compensator_design.py, whose design() this runs) finds the
thesis's elbow design, R_out 49.6 mm at R_in 35 mm for 1.58 x the Table 4.2 torque (sec.
4.4.1), and its optimum is what `magfem study` computes for the same radii.
Skipped when scipy (python3-scipy) is not installed. Run by ctest `python_compensator_design`
with MAGFEM_EXE and PYTHONPATH=build/python (~3 s)."""
import csv
import importlib.util
import os
import subprocess
import tempfile
import unittest

import magfem

SOURCE = os.environ.get("MAGFEM_SOURCE_DIR", ".")
EXE = os.environ.get("MAGFEM_EXE", os.path.join(SOURCE, "build", "magfem"))
EXAMPLE = os.path.join(SOURCE, "examples", "python", "compensator_design.py")

try:
    import scipy.optimize  # noqa: F401
    HAVE_SCIPY = True
except ImportError:
    HAVE_SCIPY = False


def load_example():
    spec = importlib.util.spec_from_file_location("compensator_design", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def cli_peak_torques(r_out, r_in_values):
    """peak_torque_Nm of `magfem study` at R_out (mm) for each R_in, by R_in."""
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([EXE, "study", os.path.join(SOURCE, "examples", "3d",
                                                   "compensator_study.yaml"),
                        "--param", "R_out=%r" % r_out,
                        "--param", "R_in=" + ",".join("%r" % v for v in r_in_values),
                        "--objective", "peak_torque", "--rotate", "outer", "--axis", "y",
                        "--angles", "0:10:180", "--out", out],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(os.path.join(out, "study.csv"), encoding="utf-8") as f:
            return {float(r["R_in"]): float(r["peak_torque_Nm"]) for r in csv.DictReader(f)}


@unittest.skipUnless(HAVE_SCIPY, "scipy is not installed (Debian: python3-scipy)")
class ElbowDesign(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.example = load_example()
        cls.case = magfem.Case.load(cls.example.CASE)
        cls.d = cls.example.design(cls.case, r_in=35.0, factor=1.58)

    def test_finds_the_thesis_elbow(self):
        # 0.8 mm: paper_targets gives the thesis's torques 5 %, and 5 % of the 19.5 N m
        # target is 0.98 N m, 0.8 mm of R_out at the curve's slope there (dT/dR_out = 1.2 N m
        # per mm between 48.6 and 50.6 mm). Found: 49.75 mm, 0.2 % of torque from 49.6 mm.
        self.assertAlmostEqual(self.d["R_out_mm"], 49.6, delta=0.8)
        # The reference is the Table 4.2 torque of test_study.cpp (12.3653 N m, the harmonic
        # form, equal to the charge model to 1e-4 there).
        self.assertAlmostEqual(self.d["table42_Nm"], 12.3653, delta=1e-4)

    def test_the_optimum_is_the_least_magnet_meeting_the_torque(self):
        # The constraint is active at the optimum (SLSQP's ftol 1e-10 on a smooth curve) and a
        # shell 0.05 mm thinner (~0.03 N m less, far above that tolerance) falls short.
        target = self.d["target_Nm"]
        self.assertAlmostEqual(self.d["torque_Nm"] / target, 1.0, delta=1e-6)
        thinner = self.example.peak_torque(self.case, R_in=35.0, R_out=self.d["R_out_mm"] - 0.05)
        self.assertLess(thinner, target)

    def test_the_optimum_is_the_command_lines(self):
        # The same radii through `magfem study` (a process, the same analytic model): its
        # study.csv carries 10 digits, so 1e-8 relative.
        cli = cli_peak_torques(self.d["R_out_mm"], [35.0])
        self.assertAlmostEqual(cli[35.0] / self.d["torque_Nm"], 1.0, delta=1e-8)
        table42 = cli_peak_torques(43.0, [29.0])[29.0]
        self.assertAlmostEqual(cli[35.0] / table42, 1.58, delta=1e-6)


if __name__ == "__main__":
    unittest.main()

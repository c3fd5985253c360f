"""magfem.optimize (issue 32): `magfem optimize` in-process. The same problem through Python
and through a `magfem optimize` process gives the same history.csv byte for byte and the same
summary.json (write() the same files); the optimizer finds the closed-form optimum of a
dipole in a radial shell (tests/studies/test_optimize.cpp's problem); bad arguments name
their field. Run by ctest `python_optimize` with MAGFEM_EXE and PYTHONPATH=build/python."""
import csv
import json
import math
import os
import subprocess
import tempfile
import unittest

import numpy as np

import magfem

SOURCE = os.path.abspath(os.environ.get("MAGFEM_SOURCE_DIR", "."))
EXE = os.environ.get("MAGFEM_EXE", os.path.join(SOURCE, "build", "magfem"))
COMPENSATOR = os.path.join(SOURCE, "examples", "3d", "compensator_study.yaml")


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


class AgainstCommandLine(unittest.TestCase):
    """The docs' compensator problem (docs/performance.md): the largest peak torque with
    R_in in 25..40, R_out in 45..65 and R_out - R_in <= 15."""

    @classmethod
    def setUpClass(cls):
        cls.reports = []
        cls.result = magfem.optimize(
            magfem.Case.load(COMPENSATOR), vary={"R_in": (25, 40), "R_out": [45, 65]},
            maximize="peak_torque", rotate="outer", axis="y", angles=[90],
            constraints="R_out - R_in <= 15",
            progress=lambda done, total: cls.reports.append((done, total)))
        cls.tmp = tempfile.TemporaryDirectory()
        cls.cli_dir = os.path.join(cls.tmp.name, "cli")
        subprocess.run([EXE, "optimize", COMPENSATOR, "--vary", "R_in=25:40", "--vary",
                        "R_out=45:65", "--constraint", "R_out - R_in <= 15", "--maximize",
                        "peak_torque", "--rotate", "outer", "--axis", "y", "--angles", "90",
                        "--out", cls.cli_dir], check=True, stdout=subprocess.DEVNULL)
        cls.cli = json.loads(read(os.path.join(cls.cli_dir, "summary.json")))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_summary_is_the_command_lines_but_provenance(self):
        cli = {k: v for k, v in self.cli.items() if k not in ("magfem_version", "commit")}
        self.assertEqual(self.result.summary, cli)

    def test_history_is_history_csv(self):
        text = read(os.path.join(self.cli_dir, "history.csv"))
        self.assertEqual(self.result.history_csv(), text)
        rows = list(csv.DictReader(text.splitlines()))
        self.assertEqual(list(self.result.history), ["evaluation", "R_in", "R_out",
                                                     "peak_torque_Nm"])
        self.assertEqual(len(rows), self.result.evaluations)
        for name, column in self.result.history.items():
            self.assertIsInstance(column, np.ndarray)
            np.testing.assert_allclose(column, [float(r[name]) for r in rows], rtol=1e-9)

    def test_write_is_the_command_lines_output(self):
        out = os.path.join(self.tmp.name, "py")
        self.assertEqual(sorted(self.result.write(out)), ["history.csv", "summary.json"])
        for name in ("history.csv", "summary.json"):  # the same case path: byte for byte
            self.assertEqual(read(os.path.join(out, name)), read(os.path.join(self.cli_dir, name)),
                             name)

    def test_the_optimum_is_on_the_constraint(self):
        # The torque grows with both radii (Figs. 4.10-4.11), so the optimum takes the
        # largest R_in the bounds allow and the constraint's R_out: (40, 55), to xtol.
        self.assertAlmostEqual(self.result.optimum["R_in"], 40.0, delta=1e-3)
        self.assertAlmostEqual(self.result.optimum["R_out"], 55.0, delta=1e-3)
        # The best feasible point the optimizer saw is the optimum it reports (COBYLA may
        # step outside the constraint on its way, to larger torques).
        h = self.result.history
        feasible = h["R_out"] - h["R_in"] <= 15 + 1e-9
        best = h["peak_torque_Nm"][feasible].max()
        self.assertAlmostEqual(self.result.objective, best, delta=1e-9 * best)
        self.assertIsNone(self.result.fe_objective)

    def test_progress_counts_the_evaluations(self):
        self.assertEqual(self.reports[-1], (self.result.evaluations, 500))
        self.assertEqual([d for d, _ in self.reports], list(range(1, len(self.reports) + 1)))


# A uniformly magnetized sphere (radius a) in a radial hemispherical shell (a + g .. R):
# T = mu0 m (M/2) ln(R/(a+g)) at 90 deg, largest where 3 ln(R/(a+g)) = a/(a+g).
DIPOLE_IN_SHELL = {
    "dimension": 3, "unit": "mm", "parameters": {"a": 20, "gap": 1, "R": 50},
    "materials": {"pm": {"kind": "magnet", "B_r": 1.2, "mu_r": 1.0}},
    "regions": [
        {"name": "ball", "shape": "spherical_segment", "r_outer": "${a}", "theta": [0, 180],
         "material": "pm", "magnetization": {"type": "parallel", "direction": [0, 0, 1]}},
        {"name": "shell", "shape": "spherical_segment", "r_inner": "${a + gap}",
         "r_outer": "${R}", "theta": [0, 90], "material": "pm",
         "magnetization": {"type": "radial"}, "group": "shell"}],
    "boundary": {"type": "open", "radius": 80}, "mesh": {"size": 8}}


class ClosedForm(unittest.TestCase):
    def test_finds_the_optimum_of_the_dipole_in_a_shell(self):
        r = magfem.optimize(magfem.Case.from_dict(DIPOLE_IN_SHELL), vary={"a": (5, 45)},
                            maximize="peak_torque", rotate="shell", axis="y", angles=[90],
                            xtol=1e-7)
        lo, hi = 5.0, 45.0
        for _ in range(100):  # bisection on 3 ln(R/(a+g)) - a/(a+g), decreasing in a
            a = 0.5 * (lo + hi)
            if 3 * math.log(50 / (a + 1)) - a / (a + 1) > 0:
                lo = a
            else:
                hi = a
        # xtol 1e-7 relative on a ~ 20 mm; the objective is flat at the optimum, so COBYLA
        # stops within ~1e-4 mm (test_optimize.cpp's tolerance for the same run).
        self.assertAlmostEqual(r.optimum["a"], lo, delta=1e-3)
        self.assertEqual(r.summary["case"], "<dict>")

    def test_minimize_goes_the_other_way(self):
        # The compensator's torque grows with R_out: its least is at the lower bound.
        r = magfem.optimize(magfem.Case.load(COMPENSATOR), vary={"R_out": (45, 65)},
                            minimize="peak_torque", rotate="outer", axis="y", angles=[90])
        self.assertEqual(r.summary["sense"], "minimize")
        self.assertAlmostEqual(r.optimum["R_out"], 45.0, delta=1e-3)


class Arguments(unittest.TestCase):
    def test_bad_arguments_name_the_field(self):
        case = magfem.Case.load(COMPENSATOR)
        base = {"vary": {"R_out": (45, 65)}, "maximize": "peak_torque", "rotate": "outer",
                "axis": "y", "angles": [90]}
        for change, field in (({"maximize": None}, "maximize"),
                              ({"minimize": "peak_torque"}, "maximize"),
                              ({"maximize": "torque_everywhere"}, "maximize"),
                              ({"vary": {"R_out": (65, 45)}}, "vary"),
                              ({"vary": {"R_out": 45}}, "vary"),
                              ({"vary": {}}, "vary"),
                              ({"constraints": "R_in <= 3"}, "constraints"),
                              ({"xtol": 0}, "xtol"),
                              ({"axis": "w"}, "axis")):
            with self.assertRaises(magfem.InputError, msg=str(change)) as e:
                magfem.optimize(case, **{**base, **change})
            self.assertEqual(e.exception.field, field, str(change))


if __name__ == "__main__":
    unittest.main()

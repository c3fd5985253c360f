"""Case.solve(accuracy=, max_passes=, max_unknowns=) (issues 29 and 32): the adaptive solve in
Python is `magfem solve --accuracy --max-passes` in-process, so summary.json agrees but its
times, and the estimates Python hands out are the ones the loop stopped on. A limit reached
first is an AdaptWarning and adapt["converged"] False, never an exception.
Run by ctest `python_adapt` with MAGFEM_EXE and PYTHONPATH=build/python (~6 s)."""
import json
import os
import subprocess
import sys
import tempfile
import unittest
import warnings

import yaml

import magfem

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_solve import EXE, but_times, example  # noqa: E402

SOLENOID = example("axi/solenoid_adaptive.yaml")  # asks for 0.01 %: two passes


def cli_summary(case_path, *options):
    """summary.json of `magfem solve case options`, run in a temporary folder."""
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([EXE, "solve", case_path, "--quiet", *options, "--out", out], check=True,
                       stdout=subprocess.DEVNULL)
        with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
            return json.load(f)


def solve_quietly(case, **kw):
    """case.solve(**kw) and the AdaptWarnings it gave."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sol = case.solve(**kw)
    return sol, [w for w in caught if issubclass(w.category, magfem.AdaptWarning)]


class Accuracy(unittest.TestCase):
    """accuracy= over the case's 0.01 %: the command line's --accuracy 0.05."""

    @classmethod
    def setUpClass(cls):
        cls.notes = []
        cls.sol, cls.warned = solve_quietly(
            magfem.Case.load(SOLENOID), accuracy=0.05,
            progress=lambda kind, text: cls.notes.append(text) if kind == "note" else None)
        cls.cli = cli_summary(SOLENOID, "--accuracy", "0.05")

    def test_summary_is_the_command_lines_but_times(self):
        self.assertEqual(but_times(self.sol.summary), but_times(self.cli))

    def test_the_accuracy_reaches_the_loop(self):
        adapt = self.sol.adapt
        self.assertEqual(adapt["accuracy_pct"], 0.05)  # not the case's 0.01
        self.assertTrue(adapt["converged"])
        self.assertEqual(self.warned, [])
        # 0.05 % is met on the second pass (the case's own 0.01 % too): the energy by the
        # estimator, the axis field by the change between the passes.
        self.assertEqual(len(adapt["passes"]), 2)
        for quantity in ("energy", "probes.axis"):
            self.assertLessEqual(adapt["estimates"][quantity]["error_pct"], 0.05, quantity)
        self.assertEqual(adapt["estimates"]["energy"]["value"], self.sol.energy)
        self.assertEqual(self.sol.energy_error_pct, adapt["passes"][-1]["energy_error_pct"])
        self.assertEqual(self.sol.probe_error_pct,
                         {"axis": adapt["passes"][-1]["quantity_error_pct"]["probes.axis"]})

    def test_passes_come_as_progress_notes(self):
        passes = [n for n in self.notes if n.startswith("pass ")]
        self.assertEqual(len(passes), len(self.sol.adapt["passes"]))


class MaxPasses(unittest.TestCase):
    """max_passes=1 under the case's 0.01 % (met on pass 2): stops early, warns, returns the
    last pass."""

    @classmethod
    def setUpClass(cls):
        cls.sol, cls.warned = solve_quietly(magfem.Case.load(SOLENOID), max_passes=1)
        cls.cli = cli_summary(SOLENOID, "--max-passes", "1")

    def test_summary_is_the_command_lines_but_times(self):
        self.assertEqual(but_times(self.sol.summary), but_times(self.cli))

    def test_the_limit_warns_and_is_not_converged(self):
        adapt = self.sol.adapt
        self.assertFalse(adapt["converged"])
        self.assertEqual(len(adapt["passes"]), 1)
        self.assertIn("max_passes (1) reached", adapt["stop_reason"])
        self.assertEqual(len(self.warned), 1)
        self.assertIn("max_passes (1) reached", str(self.warned[0].message))
        self.assertIn(str(self.warned[0].message), self.sol.summary["warnings"])

    def test_max_unknowns_stops_too(self):
        # The second pass of this case predicts ~10^4 unknowns or more: 5000 stops after one.
        sol, warned = solve_quietly(magfem.Case.load(SOLENOID), accuracy=0.05,
                                    max_unknowns=5000)
        self.assertFalse(sol.adapt["converged"])
        self.assertEqual(len(sol.adapt["passes"]), 1)
        self.assertIn("max_unknowns", sol.adapt["stop_reason"])
        self.assertEqual(len(warned), 1)


class ForceEstimates(unittest.TestCase):
    """A force named as an adapt quantity carries its estimate in sol.forces."""

    def test_force_error_is_the_loops(self):
        with open(example("axi/voice_coil_magnet.yaml"), encoding="utf-8") as f:
            d = yaml.safe_load(f)
        d["adapt"] = {"accuracy_pct": 1, "quantities": ["forces.coil_lorentz.Fz"]}
        case = magfem.Case.from_dict(d)
        sol, warned = solve_quietly(case, mesh_scale=2.0, max_passes=3)
        with tempfile.NamedTemporaryFile("w", suffix=".yaml", dir=os.path.dirname(
                example("axi/voice_coil_magnet.yaml")), delete=False) as f:
            f.write(case.to_yaml())  # beside the example: relative paths resolve alike
        try:
            cli = cli_summary(f.name, "--mesh-scale", "2", "--max-passes", "3")
        finally:
            os.unlink(f.name)
        self.assertEqual(warned, [])
        mine = but_times(sol.summary)
        # The title and file name differ (<dict> against the temporary file's name).
        for s in (mine, cli):
            s.pop("case", None)
        self.assertEqual(mine, but_times(cli))
        last = sol.adapt["passes"][-1]
        error = sol.forces["coil_lorentz"]["error_pct"]
        self.assertEqual(list(error), ["Fz"])
        self.assertEqual(error["Fz"], last["quantity_error_pct"]["forces.coil_lorentz.Fz"])
        self.assertLessEqual(error["Fz"], 1.0)
        self.assertNotIn("error_pct", sol.forces["magnet_stress"])  # not a named quantity


class Arguments(unittest.TestCase):
    def test_bad_arguments_name_the_field(self):
        case = magfem.Case.load(example("axi/solenoid.yaml"))  # no adapt: section
        for kw, field in (({"accuracy": 0}, "accuracy"), ({"accuracy": 100}, "accuracy"),
                          ({"accuracy": 1, "max_passes": 0}, "max_passes"),
                          ({"accuracy": 1, "max_passes": 2.5}, "max_passes"),
                          ({"accuracy": 1, "max_unknowns": -1}, "max_unknowns"),
                          ({"max_passes": 3}, "max_passes"),  # limits without an accuracy
                          ({"max_unknowns": 1e5}, "max_unknowns")):
            with self.assertRaises(magfem.InputError, msg=str(kw)) as e:
                case.solve(**kw)
            self.assertEqual(e.exception.field, field, str(kw))

    def test_no_accuracy_no_adapt_block(self):
        sol = magfem.Case.load(example("axi/solenoid.yaml")).solve(mesh_scale=2.0)
        self.assertIsNone(sol.adapt)
        self.assertNotIn("adapt", sol.summary)
        self.assertGreater(sol.energy_error_pct, 0)


if __name__ == "__main__":
    unittest.main()

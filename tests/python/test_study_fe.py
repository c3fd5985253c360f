"""magfem.study with FE designs (analytic=False) and the adaptive arguments accuracy=,
max_passes=, max_unknowns= (issues 29 and 32) against `magfem study --fe`.

Both run the same library call (studies/study.hpp run_study), so for the same case and
options study.csv must be the same bytes, `_err` columns included, and summary.json the same
but its times and provenance. The case: two hemispherical magnets at a third of the
compensator's size, meshed coarsely at order 1, two designs (R_out 26 and 30 mm), the torque
at 90 deg, at mesh_scale 3: about a second a design. With accuracy= every design runs the
adaptive loop: one pass in the default suite (ctest `python_study_fe`, ~20 s loaded; the
loop stops at max_passes, so each design is a warning), two with MAGFEM_TEST_LONG=1 (ctest
`python_study_fe_long`, label long, ~90 s loaded: the refined pass, converged). A Python call
that dropped the accuracy would have no `adapt` records or warnings (and, over two passes,
other torques). Run with MAGFEM_EXE and PYTHONPATH=build/python."""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

import numpy as np

import magfem

SOURCE = os.environ.get("MAGFEM_SOURCE_DIR", ".")
EXE = os.environ.get("MAGFEM_EXE", os.path.join(SOURCE, "build", "magfem"))

# The small coarse compensator of tests/cli/test_mpi_studies.cpp (R_out a parameter).
SMALL_COMPENSATOR = os.path.join(SOURCE, "tests", "cli", "small_compensator.yaml")
GRID = dict(params={"R_out": [26, 30]}, objectives="torque_at:90", rotate="outer", axis="y",
            analytic=False, order=1, mesh_scale=3.0, jobs=1)
CLI_GRID = ["--param", "R_out=26,30", "--objective", "torque_at:90", "--rotate", "outer",
            "--axis", "y", "--fe", "--order", "1", "--mesh-scale", "3", "--jobs", "1",
            "--quiet"]
PASSES = 2 if os.environ.get("MAGFEM_TEST_LONG") == "1" else 1
ADAPT = dict(accuracy=5.0, max_passes=PASSES)
CLI_ADAPT = ["--accuracy", "5", "--max-passes", str(PASSES)]


def without_times(summary):
    """summary.json but its provenance and times (which differ run to run)."""
    return {k: v for k, v in summary.items()
            if k not in ("magfem_version", "commit", "build", "seconds")}


class FeStudy(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp()
        cls.path = SMALL_COMPENSATOR
        cls.case = magfem.Case.load(cls.path)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir)

    def cli(self, extra):
        """`magfem study` on the case; returns study.csv and summary.json."""
        out = tempfile.mkdtemp(dir=self.dir)
        run = subprocess.run([EXE, "study", self.path, *CLI_GRID, *extra, "--out", out],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        with open(os.path.join(out, "study.csv"), encoding="utf-8") as f:
            csv = f.read()
        with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
            return csv, json.load(f)

    def check_same(self, result, csv, summary):
        # study.csv byte for byte: the same library call, the same designs.
        self.assertEqual(result.csv(), csv)
        header = csv.splitlines()[0].split(",")
        self.assertEqual(result.columns, header)
        self.assertEqual(header, ["R_out", "torque_at_90deg_Nm", "torque_at_90deg_Nm_err"])
        # The estimate is there (every FE torque has one) and bounds a few per cent: the
        # numpy column, not only its text.
        err = result["torque_at_90deg_Nm_err"]
        self.assertTrue(np.all(err > 0), err)
        self.assertTrue(np.all(err < 0.2 * np.abs(result["torque_at_90deg_Nm"])), err)
        self.assertEqual(without_times(result.summary), without_times(summary))

    def test_one_mesh_per_design_as_the_command_line(self):
        csv, summary = self.cli([])
        result = magfem.study(self.case, **GRID)
        self.check_same(result, csv, summary)
        self.assertEqual(result.adapt, [])  # nothing asked an accuracy

    def test_accuracy_as_the_command_line(self):
        csv, summary = self.cli(CLI_ADAPT)
        result = magfem.study(self.case, **GRID, **ADAPT)
        self.check_same(result, csv, summary)
        # Every design ran the loop to its max_passes (one pass cannot estimate a change, so
        # it stops there, a warning; two reach 5 %, measured 0.7 % and 0.3 %).
        self.assertEqual([a["parameters"] for a in result.adapt], [[26.0], [30.0]])
        self.assertTrue(all(a["passes"] == PASSES for a in result.adapt), result.adapt)
        self.assertEqual(len(result.warnings),
                         sum(not a["converged"] for a in result.adapt))
        self.assertEqual(len(result.warnings), 2 if PASSES == 1 else 0, result.warnings)

    def test_bad_arguments_name_the_field(self):
        # The command line's checks and messages (casefile/cli_number parse_cli_adapt), the
        # argument's name in place of the option's; nothing is solved before they fail.
        for kwargs, field, words in [
                (dict(accuracy=0), "accuracy", "between 0 and 100"),
                (dict(accuracy=100), "accuracy", "between 0 and 100"),
                (dict(accuracy=float("nan")), "accuracy", "finite number"),
                (dict(accuracy=1, max_passes=0), "max_passes", "whole number"),
                (dict(accuracy=1, max_passes=2.5), "max_passes", "whole number"),
                (dict(accuracy=1, max_unknowns=-1), "max_unknowns", "positive"),
                (dict(max_passes=3), "max_passes", "accuracy")]:
            with self.assertRaises(magfem.InputError, msg=str(kwargs)) as err:
                magfem.study(self.case, **{**GRID, **kwargs})
            self.assertEqual(err.exception.field, field, str(kwargs))
            self.assertEqual(err.exception.file, "<study>", str(kwargs))
            self.assertIn(words, str(err.exception), str(kwargs))
        # Refused with the analytic models, as --accuracy without --fe.
        with self.assertRaises(magfem.InputError) as err:
            magfem.study(self.case, **{**GRID, "analytic": True}, accuracy=1)
        self.assertEqual(err.exception.field, "accuracy")
        self.assertIn("analytic=False", str(err.exception))


if __name__ == "__main__":
    unittest.main()

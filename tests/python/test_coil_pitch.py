"""magfem.coil_pitch (issue 32): the thesis's coil-pitch study (`magfem actuator --analytic
--coil-pitch`, sec. 5.3) in-process, against the command line.

On the topology case, two pitches over two orientations by the charge model (one radial
Gauss point a coil, so that the rotor's field is tabulated on one sphere, not four: seconds,
not a minute, and a rule the call must pass on to give the command line's bytes): coil_pitch.csv
byte for byte as the command line writes it, the numpy columns the CSV's numbers, summary.json
but its times; the pitches reach the study (the array's coil count follows the thesis's rule,
the pitch list as text or numbers gives the same table); bad arguments are refused with the
command line's messages. Run by ctest `python_coil_pitch` with MAGFEM_EXE and
PYTHONPATH=build/python (~8 s)."""
import json
import os
import subprocess
import tempfile
import unittest

import numpy as np

import magfem

SOURCE = os.environ.get("MAGFEM_SOURCE_DIR", ".")
EXE = os.environ.get("MAGFEM_EXE", os.path.join(SOURCE, "build", "magfem"))
CASE = os.path.join(SOURCE, "examples", "3d", "spherical_actuator_topology.yaml")
ORIENTATIONS = "rx=0,20"
PITCHES = "50:10:60"
QUADRATURE = "1,3,2,32"
# What differs between two runs of the same study: times, and the provenance (the executable
# and the module may be built at different commits).
TIMES = ("seconds", "table_seconds", "study_seconds", "magfem_version", "git_commit")


def cli(*args):
    """`magfem actuator CASE --rotor rotor ... --out TMP`: (exit code, stderr, {file: text})."""
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([EXE, "actuator", CASE, "--rotor", "rotor", *args, "--out", out],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        files = {}
        for name in os.listdir(out):
            if name.endswith((".csv", ".json")):
                with open(os.path.join(out, name), encoding="utf-8") as f:
                    files[name] = f.read()
        return run.returncode, run.stderr, files


class CoilPitch(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        code, _, cls.files = cli("--orientations", ORIENTATIONS, "--analytic", "--coil-pitch",
                                 PITCHES, "--coil-quadrature", QUADRATURE)
        assert code == 0
        cls.case = magfem.Case.load(CASE)
        cls.result = magfem.coil_pitch(cls.case, rotor="rotor", orientations=ORIENTATIONS,
                                       pitches=PITCHES, coil_quadrature=QUADRATURE)

    def test_the_table_is_the_command_lines(self):
        # Byte for byte: the same library call on the same orientations and pitches.
        self.assertEqual(self.result.csv(), self.files["coil_pitch.csv"])
        # The columns, under the CSV's names, are its numbers in full precision (within one
        # unit of the tenth digit the CSV keeps).
        lines = self.files["coil_pitch.csv"].splitlines()
        header = lines[0].split(",")
        self.assertEqual(self.result.columns, header)
        table = np.array([[float(x) for x in line.split(",")] for line in lines[1:]])
        for k, name in enumerate(header):
            np.testing.assert_allclose(self.result[name], table[:, k], rtol=1e-9, atol=0,
                                       err_msg=name)
        # P_mean is the average of P_x, P_y, P_z (Table 5.4), to round-off.
        r = self.result
        np.testing.assert_allclose(r["P_mean_W"], (r["P_x_W"] + r["P_y_W"] + r["P_z_W"]) / 3,
                                   rtol=1e-15)
        summary = json.loads(self.files["summary.json"])
        for key in TIMES:
            summary.pop(key, None)
            r.summary.pop(key, None)
        self.assertEqual(r.summary, summary)
        self.assertEqual(r.minimum["coil_pitch_deg"],
                         r["coil_pitch_deg"][np.argmin(r["P_mean_W"])])

    def test_the_pitches_reach_the_study(self):
        r = self.result
        np.testing.assert_array_equal(r["coil_pitch_deg"], [50, 60])
        # The thesis's rule: min(7, floor(360 / pitch)) coils a row, two rows.
        np.testing.assert_array_equal(r["n_coils"], [14, 12])
        # Coil size, eqs. 5.5-5.7: G_w + C_w = 0.9 sqrt(2) pitch / 4.
        np.testing.assert_allclose(r["G_w_deg"] + r["C_w_deg"],
                                   0.9 * np.sqrt(2) * r["coil_pitch_deg"] / 4, rtol=1e-12)
        # The pitches as numbers, the orientations as rows and the rule as integers give the
        # same table.
        again = magfem.coil_pitch(self.case, "rotor", [[0, 0, 0], [20, 0, 0]], [50, 60],
                                  coil_quadrature=(1, 3, 2, 32))
        self.assertEqual(again.csv(), r.csv())

    def test_bad_arguments_are_refused_with_the_command_lines_messages(self):
        for pitches, option in (("5:5:60", "--coil-pitch"), ("50:x:60", "--coil-pitch")):
            with self.assertRaises(magfem.InputError) as err:
                magfem.coil_pitch(self.case, "rotor", ORIENTATIONS, pitches)
            self.assertEqual(err.exception.field, "pitches")
            code, stderr, files = cli("--orientations", ORIENTATIONS, "--analytic",
                                      "--coil-pitch", pitches)
            self.assertEqual((code, files), (2, {}))
            reason = str(err.exception).split("'pitches': ", 1)[1]
            self.assertIn("'%s': %s" % (option, reason), stderr)
        with self.assertRaises(magfem.InputError) as err:
            magfem.coil_pitch(self.case, "rotor", "rx=a", PITCHES)
        self.assertEqual(err.exception.field, "orientations")
        with self.assertRaises(magfem.InputError) as err:
            magfem.coil_pitch(self.case, "rotor", ORIENTATIONS, PITCHES,
                              coil_quadrature=(0, 3, 2, 32))
        self.assertEqual(err.exception.field, "coil_quadrature")
        with self.assertRaises(magfem.InputError):
            magfem.coil_pitch(self.case, "stator", ORIENTATIONS, PITCHES)


if __name__ == "__main__":
    unittest.main()

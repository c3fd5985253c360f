"""magfem.sweep (issue 32): the in-process sweep gives the numbers `magfem sweep` writes for
the same case (sweep.csv byte for byte, summary.json but times and provenance), for the 3D
analytic compensator curve, a planar FE rotor and an axisymmetric FE translation; its
arguments reach the library; Ctrl-C stops it. Run by ctest `python_studies` with MAGFEM_EXE
and PYTHONPATH=build/python; coarse meshes keep it near 15 s."""
import json
import os
import signal
import subprocess
import tempfile
import threading
import time
import unittest

import numpy as np

import magfem

SOURCE = os.environ.get("MAGFEM_SOURCE_DIR", ".")
EXE = os.environ.get("MAGFEM_EXE", os.path.join(SOURCE, "build", "magfem"))


def example(name):
    return os.path.join(SOURCE, "examples", name)


def cli(command, *args):
    """Runs `magfem COMMAND ARGS --out TMP`; returns {file name: text} of what it wrote."""
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([EXE, command, *args, "--out", out], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        texts = {}
        for name in os.listdir(out):
            if name.endswith((".csv", ".json")):
                with open(os.path.join(out, name), encoding="utf-8") as f:
                    texts[name] = f.read()
        return texts


def without_times(summary):
    """summary.json but what differs between two runs of the same positions: times, the
    provenance and the peak memory (the Python summary has neither of the last two)."""
    keep = {k: v for k, v in summary.items()
            if k not in ("magfem_version", "commit", "build", "peak_memory_MB")}
    keep["positions"] = [{k: v for k, v in p.items() if k != "seconds"}
                         for p in summary["positions"]]
    return keep


class AgainstCommandLine(unittest.TestCase):
    def check_same(self, result, files):
        # sweep.csv byte for byte: the same library call, the same rows.
        self.assertEqual(result.csv(), files["sweep.csv"])
        # The numpy columns in full precision round to the CSV's digits (within one unit of
        # the tenth digit), column by column under the CSV's own header names.
        lines = files["sweep.csv"].splitlines()
        header = lines[0].split(",")
        self.assertEqual(result.columns, header)
        table = np.array([[float(x) for x in line.split(",")] for line in lines[1:]])
        for k, name in enumerate(header):
            np.testing.assert_allclose(result[name], table[:, k], rtol=1e-9, atol=1e-12,
                                       err_msg=name)
        summary = json.loads(files["summary.json"])
        self.assertEqual(without_times(result.summary), without_times(summary))

    def test_analytic_compensator_curve(self):
        # Thesis Table 4.2 compensator, outer shell tilted about y: the harmonic interaction.
        path = example("3d/compensator_table42.yaml")
        files = cli("sweep", path, "--rotate", "outer", "--axis", "y", "--angles", "0:10:180",
                    "--analytic", "--quiet")
        result = magfem.sweep(magfem.Case.load(path), rotate="outer", axis="y",
                              angles=np.arange(0, 181, 10), analytic=True)
        self.check_same(result, files)
        self.assertEqual(len(result["angle_deg"]), 19)
        # Symmetry: aligned (0 deg) and reversed (180 deg) shells feel no torque; within the
        # series' truncation bound stated per position.
        bound = max(p["torque_bound_Nm"] for p in result.positions)
        self.assertLess(abs(result["Ty"][0]), bound + 1e-12)
        self.assertLess(abs(result["Ty"][-1]), bound + 1e-12)
        self.assertGreater(np.abs(result["Ty"]).max(), 1e3 * bound)

    def test_planar_fe_rotor(self):
        path = example("2d/re25_motor_torque.yaml")
        files = cli("sweep", path, "--rotate", "rotor", "--axis", "z", "--angles", "0,60",
                    "--mesh-scale", "3", "--jobs", "1", "--quiet")
        result = magfem.sweep(magfem.Case.load(path), rotate="rotor", angles=[0, 60],
                              mesh_scale=3.0, jobs=1)
        self.check_same(result, files)
        self.assertEqual(result.summary["jobs"], {"requested": 1, "used": 1})

    def test_axisymmetric_fe_translation(self):
        path = example("axi/voice_coil_magnet.yaml")
        files = cli("sweep", path, "--move", "coil", "--axis", "z", "--positions", "0:3:3",
                    "--mesh-scale", "3", "--order", "1", "--quiet")
        result = magfem.sweep(magfem.Case.load(path), translate="coil", positions=[0, 3],
                              mesh_scale=3.0, order=1)
        self.check_same(result, files)
        self.assertEqual(result.columns, ["position_mm", "Fz_N"])


class Arguments(unittest.TestCase):
    COMPENSATOR = example("3d/compensator_table42.yaml")

    def test_progress_called_on_the_calling_thread(self):
        seen = []
        magfem.sweep(magfem.Case.load(self.COMPENSATOR), rotate="outer", angles=[0, 30, 60],
                     analytic=True, jobs=2,
                     progress=lambda done, total: seen.append(
                         (done, total, threading.current_thread() is threading.main_thread())))
        self.assertEqual(seen, [(1, 3, True), (2, 3, True), (3, 3, True)])

    def test_axis_and_point_reach_the_sweep(self):
        case = magfem.Case.load(self.COMPENSATOR)
        about_y = magfem.sweep(case, rotate="outer", axis=[0, 2, 0], angles=[30], analytic=True)
        about_x = magfem.sweep(case, rotate="outer", axis="x", angles=[30], analytic=True)
        self.assertEqual(about_y.summary["axis"], [0, 1, 0])  # normalized, as --axis 0,2,0
        # Tilted about x the torque is about x (Tx), not y: the axis was not ignored.
        self.assertGreater(abs(about_x["Tx"][0]), 1e3 * abs(about_x["Ty"][0]))
        self.assertGreater(abs(about_y["Ty"][0]), 1e3 * abs(about_y["Tx"][0]))

    def test_bad_arguments_name_the_field(self):
        case = magfem.Case.load(self.COMPENSATOR)
        for kwargs, field in [(dict(rotate="outer", translate="outer", positions=[0]), "rotate"),
                              (dict(rotate="outer"), "angles"),
                              (dict(rotate="outer", angles=[0], jobs=0), "jobs"),
                              (dict(rotate="nobody", angles=[0], analytic=True), "--rotate")]:
            with self.assertRaises(magfem.InputError, msg=str(kwargs)) as err:
                magfem.sweep(case, **kwargs)
            self.assertEqual(err.exception.field, field)
        axi = magfem.Case.load(example("axi/voice_coil_magnet.yaml"))
        with self.assertRaises(magfem.InputError) as err:
            magfem.sweep(axi, translate="coil", positions=[0], analytic=True)
        self.assertEqual(err.exception.field, "analytic")

    def test_ctrl_c_stops_before_the_next_position(self):
        # One FE position at a time: a real SIGINT, as the terminal sends, 0.2 s in stops the
        # sweep after the position under way, well before the 12 positions are done. The
        # bound is in units of one position's time, measured first (the machine is shared).
        case = magfem.Case.load(example("axi/voice_coil_magnet.yaml"))
        t0 = time.perf_counter()
        magfem.sweep(case, translate="coil", positions=[0], mesh_scale=3.0, jobs=1)
        one = time.perf_counter() - t0
        threading.Timer(0.2, os.kill, (os.getpid(), signal.SIGINT)).start()
        t0 = time.perf_counter()
        with self.assertRaises(KeyboardInterrupt):
            magfem.sweep(case, translate="coil", positions=np.arange(12.0), mesh_scale=3.0,
                         jobs=1)
        elapsed = time.perf_counter() - t0
        print("one position %.2f s; interrupted after %.2f s" % (one, elapsed))
        self.assertLess(elapsed, 0.2 + 4 * one)

if __name__ == "__main__":
    unittest.main()

"""magfem.sweep, magfem.actuator and magfem.validate (issue 32) against the command line.

The in-process sweep gives the numbers `magfem sweep` writes for the same case (sweep.csv
byte for byte, summary.json but times and provenance), for the 3D analytic compensator
curve, a planar FE rotor and an axisymmetric FE translation; its arguments reach the
library; Ctrl-C stops it. The actuator's arrays rebuild `magfem actuator`'s CSV files byte
for byte and satisfy the commutation identity; validate's rows are results.json's entries.
Run by ctest `python_studies` with MAGFEM_EXE and PYTHONPATH=build/python; coarse meshes
keep it near 25 s."""
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
            if name.endswith((".csv", ".json")) and not name.startswith("."):
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


    def test_planar_fe_translation(self):
        # Two line-dipole cylinders pulled apart along x: the planar translate sweep, the
        # same library call as `magfem sweep --move`, so the same bytes; the direction given
        # as two numbers in the plane, the torque point (case unit) carried with the group.
        path = example("2d/diametric_pair_translate.yaml")
        files = cli("sweep", path, "--move", "mover", "--axis", "2,0", "--positions", "0,5",
                    "--point", "15,0,0", "--mesh-scale", "3", "--jobs", "1", "--quiet")
        result = magfem.sweep(magfem.Case.load(path), translate="mover", axis=[2, 0],
                              positions=[0, 5], point=[15, 0, 0], mesh_scale=3.0, jobs=1)
        self.check_same(result, files)
        self.assertEqual(result.columns[0], "position_mm")
        self.assertEqual(result.summary["motion"], "translate")
        # F ~ 1/r^3: from r = 15 to 20 mm the attraction falls to (15/20)^3 = 0.42 (within
        # the coarse mesh's few per cent): the positions were taken in mm.
        self.assertAlmostEqual(result["Fx"][1] / result["Fx"][0], 0.4219, delta=0.02)

    def test_3d_translation(self):
        # The 3D translate sweep (two dipole spheres pulled apart along z), analytic and FE:
        # the same library call as `magfem sweep --move`, so the same bytes.
        path = example("3d/two_spheres.yaml")
        files = cli("sweep", path, "--move", "arm", "--axis", "z", "--positions", "0:2:4",
                    "--analytic", "--quiet")
        result = magfem.sweep(magfem.Case.load(path), translate="arm", axis="z",
                              positions=[0, 2, 4], analytic=True)
        self.check_same(result, files)
        self.assertEqual(result.columns[0], "position_mm")
        self.assertEqual(result.summary["motion"], "translate")
        # Moved apart along z the attraction weakens: the positions were not ignored.
        self.assertGreater(abs(result["Fz"][0]), abs(result["Fz"][2]))
        files = cli("sweep", path, "--move", "arm", "--axis", "x", "--positions", "3",
                    "--mesh-scale", "3", "--order", "1", "--jobs", "1", "--quiet")
        fe = magfem.sweep(magfem.Case.load(path), translate="arm", axis="x", positions=[3],
                          mesh_scale=3.0, order=1, jobs=1)
        self.check_same(fe, files)

    def test_3d_translation_torque_about_a_carried_point(self):
        # point= on a 3D translation, as --point: the torque about the point carried with the
        # group. A rigid-body identity against the sweep about the origin: T_P = T_0 - P x F
        # with P the point moved by the offset (mm); the charge cubature's tolerance (1e-6)
        # bounds the difference, 1e-5 of |T_0| + |P||F| allowed. Would fail on the point left
        # behind, the offset's sign or mm read as m.
        case = magfem.Case.load(example("3d/two_spheres.yaml"))
        kwargs = dict(translate="arm", axis="z", positions=[0, 3], analytic=True)
        about_origin = magfem.sweep(case, **kwargs)
        about_point = magfem.sweep(case, point=[2, -1, 14], **kwargs)
        self.assertEqual(about_point.summary["torque_point_m"], [0.002, -0.001, 0.014])
        for i, offset in enumerate([0, 3]):
            p = 1e-3 * np.array([2, -1, 14 + offset])
            f = np.array([about_origin[c][i] for c in ("Fx", "Fy", "Fz")])
            t0 = np.array([about_origin[c][i] for c in ("Tx", "Ty", "Tz")])
            tp = np.array([about_point[c][i] for c in ("Tx", "Ty", "Tz")])
            scale = np.linalg.norm(t0) + np.linalg.norm(p) * np.linalg.norm(f)
            np.testing.assert_allclose(tp, t0 - np.cross(p, f), rtol=0, atol=1e-5 * scale)


class Study(unittest.TestCase):
    PATH = example("3d/compensator_study.yaml")
    GRID = dict(params={"R_out": [40, 50, 60], "R_in": [30, 35]},
                objectives=["peak_torque", "torque_at:90"], rotate="outer", axis="y",
                angles=np.arange(0, 181, 30))

    def test_against_the_command_line(self):
        # The analytic compensator study (harmonic form, milliseconds a design): the same
        # library call as `magfem study`, so study.csv byte for byte and the same summary.
        files = cli("study", self.PATH, "--param", "R_out=40:10:60", "--param", "R_in=30,35",
                    "--objective", "peak_torque", "--objective", "torque_at:90",
                    "--rotate", "outer", "--axis", "y", "--angles", "0:30:180", "--quiet")
        seen = []
        result = magfem.study(magfem.Case.load(self.PATH),
                              progress=lambda done, total: seen.append((done, total)),
                              **self.GRID)
        self.assertEqual(result.csv(), files["study.csv"])
        self.assertEqual(result.columns, ["R_out", "R_in", "peak_torque_Nm", "torque_at_90deg_Nm"])
        cli_summary = json.loads(files["summary.json"])
        for key in ("magfem_version", "commit", "build", "seconds"):
            cli_summary.pop(key, None)
            result.summary.pop(key, None)
        self.assertEqual(result.summary, cli_summary)
        self.assertEqual(seen, [(i, 6) for i in range(1, 7)])
        # The thesis's elbow: the peak torque grows with R_out at fixed R_in (the values reach
        # the designs; the last parameter varies fastest).
        peak = result["peak_torque_Nm"][result["R_in"] == 35]
        self.assertTrue(np.all(np.diff(peak) > 0), peak)

    def test_the_case_parameters_stay_under_the_grid(self):
        # A Case loaded with gap=3 keeps it in every design: a wider gap, a weaker torque.
        base = magfem.study(magfem.Case.load(self.PATH), **self.GRID)
        wide = magfem.study(magfem.Case.load(self.PATH, params={"gap": 3}), **self.GRID)
        self.assertTrue(np.all(np.abs(wide["peak_torque_Nm"]) < np.abs(base["peak_torque_Nm"])))

    def test_bad_arguments_name_the_field(self):
        case = magfem.Case.load(self.PATH)
        for kwargs, field in [(dict(self.GRID, params={}), "params"),
                              (dict(self.GRID, objectives=[]), "objectives"),
                              (dict(self.GRID, angles=None), "angles"),
                              (dict(self.GRID, objectives="peak"), "--objective"),
                              (dict(self.GRID, params={"nobody": [1]}), "--param")]:
            with self.assertRaises(magfem.InputError, msg=str(kwargs)) as err:
                magfem.study(case, **kwargs)
            self.assertEqual(err.exception.field, field)


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
        for kwargs, field in [(dict(translate="outer", positions=[0], analytic=True), "axis")]:
            with self.assertRaises(magfem.InputError, msg=str(kwargs)) as err:
                magfem.sweep(case, **kwargs)
            self.assertEqual(err.exception.field, field)
        planar = magfem.Case.load(example("2d/re25_motor_torque.yaml"))
        for kwargs, field in [(dict(axis="z"), "--axis"),  # out of the plane
                              (dict(axis="x", analytic=True), "--analytic")]:
            with self.assertRaises(magfem.InputError, msg=str(kwargs)) as err:
                magfem.sweep(planar, translate="rotor", positions=[0], **kwargs)
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


def number(v):
    """A CSV cell as studies/actuator.cpp writes it: ten digits, "inf", or empty for NaN."""
    return "" if np.isnan(v) else "inf" if np.isinf(v) else "%.10g" % v


class Actuator(unittest.TestCase):
    """The thesis's spherical actuator by the charge model at two orientations."""
    CASE = example("3d/spherical_actuator_design.yaml")
    ORIENTATIONS = "rx=0:30:30,ry=15,rz=0"

    @classmethod
    def setUpClass(cls):
        cls.files = cli("actuator", cls.CASE, "--rotor", "rotor", "--orientations",
                        cls.ORIENTATIONS, "--analytic", "--quiet")
        cls.result = magfem.actuator(magfem.Case.load(cls.CASE), rotor="rotor",
                                     orientations=cls.ORIENTATIONS)

    def angles(self, i):
        return ",".join(number(a) for a in self.result.orientations_deg[i])

    def test_torque_constants_are_the_command_lines(self):
        r = self.result
        self.assertEqual(r.gamma.shape, (2, 3, len(r.coils)))
        lines = ["rx_deg,ry_deg,rz_deg,coil,kx,ky,kz"]
        for i in range(len(r.orientations_deg)):
            for k, coil in enumerate(r.coils):
                lines.append(",".join([self.angles(i), coil] + [number(g) for g in r.gamma[i, :, k]]))
        self.assertEqual("\n".join(lines) + "\n", self.files["torque_constants.csv"])

    def test_commutations_are_the_command_lines(self):
        r = self.result
        self.assertEqual(sorted(r.commutations), ["P_x", "P_y", "P_z"])
        for name, d in r.commutations.items():
            lines = ["rx_deg,ry_deg,rz_deg," + ",".join("i_%s_A" % c for c in r.coils)
                     + ",P_W,i_peak_A,cond_Gamma"]
            for i in range(len(r.orientations_deg)):
                cells = [number(x) for x in d["currents_A"][i]]
                cells += [number(d["P_W"][i]), number(d["i_peak_A"][i]),
                          number(d["cond_Gamma"][i])]
                lines.append(self.angles(i) + "," + ",".join(cells))
            self.assertEqual("\n".join(lines) + "\n",
                             self.files["commutation_%s.csv" % name[-1]], msg=name)

    def test_commutation_identity(self):
        # Gamma i = T_d (eq. 5.4 solves it exactly: round-off of a 3 x 12 least-norm solve)
        # and P = sum R_k i_k^2.
        r = self.result
        for name, d in r.commutations.items():
            for i in range(len(r.orientations_deg)):
                np.testing.assert_allclose(r.gamma[i] @ d["currents_A"][i], d["torque_Nm"],
                                           atol=1e-9, err_msg=name)
                self.assertAlmostEqual(d["P_W"][i],
                                       float(r.resistance_ohm @ d["currents_A"][i] ** 2),
                                       delta=1e-9 * d["P_W"][i])

    def test_a_demanded_torque_and_an_array_of_orientations(self):
        rows = [[0, 15, 0], [30, 15, 0]]
        r = magfem.actuator(magfem.Case.load(self.CASE), "rotor", rows, torque=[0.2, 0, 0.1])
        self.assertEqual(list(r.commutations), ["T_d"])
        d = r.commutations["T_d"]
        np.testing.assert_array_equal(d["torque_Nm"], [0.2, 0, 0.1])
        np.testing.assert_array_equal(r.orientations_deg, rows)
        # Linear in the demand: the unit torques' currents combined.
        p = self.result.commutations
        np.testing.assert_allclose(d["currents_A"],
                                   0.2 * p["P_x"]["currents_A"] + 0.1 * p["P_z"]["currents_A"],
                                   rtol=1e-9, atol=1e-12)


def without_seconds(value):
    """A JSON value without its "seconds" entries at any depth (times differ run to run)."""
    if isinstance(value, dict):
        return {k: without_seconds(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [without_seconds(v) for v in value]
    return value


class Validate(unittest.TestCase):
    ENTRY = "harwin.t1.paper.max_ratio_4"

    def test_rows_are_the_command_lines_results(self):
        files = cli("validate", "--only", self.ENTRY, "--jobs", "1")
        seen = []
        result = magfem.validate(tier="quick", entries=[self.ENTRY], jobs=1,
                                 progress=lambda done, total: seen.append((done, total)))
        cli_results = json.loads(files["results.json"])
        self.assertEqual(without_seconds(result.rows), without_seconds(cli_results["entries"]))
        self.assertEqual(result.summary, cli_results["summary"])
        self.assertEqual(result.tier, "quick")
        self.assertEqual(seen, [(1, 1)])
        self.assertEqual(result.failed, [])
        table = result.table()
        self.assertEqual(table["id"], [self.ENTRY])
        # The FE ratio within the entry's tolerance of the published one (the row's own check).
        self.assertLess(abs(table["fe_error_pct"][0]), table["tolerance_pct"][0])
        # Solved to the entry's accuracy: more than one pass (the first has no estimate of the
        # probe's error), converged, on a mesh of some size.
        self.assertGreater(table["passes"][0], 1)
        self.assertEqual(table["converged"], [True])
        self.assertGreater(table["unknowns"][0], 0)

    def test_bad_arguments_name_the_field(self):
        for kwargs, field in [(dict(tier="slow"), "tier"), (dict(entries=["no.such"]), "--only"),
                              (dict(entries=[self.ENTRY], source="harwin"), "entries")]:
            with self.assertRaises(magfem.InputError, msg=str(kwargs)) as err:
                magfem.validate(**kwargs)
            self.assertEqual(err.exception.field, field)

if __name__ == "__main__":
    unittest.main()

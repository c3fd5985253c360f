"""Case.solve (issue 32): the in-process solve gives what `magfem solve` writes for the same
case, bit for bit (it is the same pipeline), and the field at points is the probes' field.
Run by ctest `python_solve` with MAGFEM_EXE (the command line) and PYTHONPATH=build/python.
Coarse meshes (--mesh-scale) keep the whole file near 10 s."""
import csv
import json
import os
import signal
import subprocess
import sys
import tempfile
import threading
import unittest

import numpy as np

import magfem

SOURCE = os.environ.get("MAGFEM_SOURCE_DIR", ".")
EXE = os.environ.get("MAGFEM_EXE", os.path.join(SOURCE, "build", "magfem"))


def example(name):
    return os.path.join(SOURCE, "examples", name)


def solve_cli(case_path, mesh_scale, out_dir, command="solve"):
    """`magfem solve` (or analytic) of the case; returns (summary, {probe: {column: array}})."""
    options = ["--mesh-scale", repr(mesh_scale), "--quiet"] if command == "solve" else []
    subprocess.run([EXE, command, case_path, *options, "--out", out_dir], check=True,
                   stdout=subprocess.DEVNULL)
    with open(os.path.join(out_dir, "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    probes = {}
    for name in summary.get("probes", []):
        with open(os.path.join(out_dir, name), encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
        probes[name[:-4]] = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
    return summary, probes


# Entries of summary.json that differ between two runs of the same case: times and memory.
RUN_TO_RUN = ("timings_s", "peak_memory_MB", "seconds", "ms_per_point")


def but_times(value):
    """summary.json without its RUN_TO_RUN entries, at any depth."""
    if isinstance(value, dict):
        return {k: but_times(v) for k, v in value.items() if k not in RUN_TO_RUN}
    if isinstance(value, list):
        return [but_times(v) for v in value]
    return value


class AgainstCommandLine:
    """One case solved both ways (mixed into the TestCases below, one solve each)."""
    case = None
    mesh_scale = 2.0

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.sol = magfem.Case.load(example(cls.case)).solve(mesh_scale=cls.mesh_scale)
        cls.cli, cls.cli_probes = solve_cli(example(cls.case), cls.mesh_scale, cls.tmp.name)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_energy_is_the_command_lines(self):
        self.assertEqual(self.sol.energy, self.cli["energy_J"])
        self.assertEqual(self.sol.summary["energy_J"], self.cli["energy_J"])
        self.assertEqual(self.sol.summary["residual_history"], self.cli["residual_history"])

    def test_summary_is_the_command_lines_but_times(self):
        # Built in memory by the writer's own summary_json_2d/3d: every key, in order.
        self.assertEqual(list(self.sol.summary), list(self.cli))
        self.assertEqual(but_times(self.sol.summary), but_times(self.cli))

    def test_forces_are_the_command_lines(self):
        forces = self.sol.forces
        self.assertEqual(list(forces), [f["name"] for f in self.cli.get("forces", [])])
        for f in self.cli.get("forces", []):
            mine = forces[f["name"]]
            self.assertIsInstance(mine["force_N"], np.ndarray)
            np.testing.assert_array_equal(mine["force_N"], f["force_N"])
            np.testing.assert_array_equal(mine["torque_Nm"], f["torque_Nm"])
        self.assertEqual(self.sol.summary.get("forces"), self.cli.get("forces"))

    def test_probes_are_the_csv_files(self):
        probes = self.sol.probes
        self.assertEqual(sorted(probes), sorted(self.cli_probes))
        for name, columns in self.cli_probes.items():
            for col, values in columns.items():  # the CSV has 10 significant digits
                np.testing.assert_allclose(probes[name][col], values, rtol=1e-9, atol=1e-12,
                                           err_msg=name + "." + col)

    def assert_B_at_probe_points(self, probe, points_mm, b_columns):
        """B(points in mm) against the probe's own B columns (the same solve, no CSV)."""
        p = self.sol.probes[probe]
        b = self.sol.B(points_mm, unit="mm")
        expected = np.column_stack([p[c] if c else np.zeros(len(points_mm)) for c in b_columns])
        # The same element and the same formula; only the point's last bit may differ
        # (mm -> m), which moves B by round-off inside an element.
        np.testing.assert_allclose(b, expected, rtol=0, atol=1e-12 * np.abs(expected).max())


class Planar(AgainstCommandLine, unittest.TestCase):
    case = "2d/re25_motor_torque.yaml"  # stress circle with check, Arkkio band, Lorentz

    def test_B_at_points_is_the_probe_field(self):
        p = self.sol.probes["midgap"]
        pts = np.column_stack([p["x"], p["y"], np.zeros_like(p["x"])])
        self.assert_B_at_probe_points("midgap", pts, ["Bx", "By", None])

    def test_mm_and_m_give_the_same_field(self):
        pts_mm = np.array([[11.9, 0.0, 0.0], [0.0, -11.9, 5.0], [3.0, 4.0, 0.0]])
        np.testing.assert_array_equal(self.sol.B(pts_mm, unit="mm"), self.sol.B(pts_mm * 1e-3))
        np.testing.assert_array_equal(self.sol.H(pts_mm, unit="mm"), self.sol.H(pts_mm * 1e-3))
        self.assertTrue(np.all(self.sol.B(pts_mm, unit="mm")[:, 2] == 0))

    def test_mesh_arrays(self):
        mesh = self.sol.mesh
        self.assertEqual(mesh.nodes.shape[1], 2)
        self.assertEqual(mesh.elements.shape, (self.cli["elements"], 3))
        self.assertEqual(len(mesh.nodes), self.cli["nodes"])
        self.assertEqual(mesh.regions.shape, (self.cli["elements"],))
        self.assertLess(mesh.elements.max(), len(mesh.nodes))
        self.assertTrue(set(np.unique(mesh.regions)) <= set(range(-2, len(mesh.region_names))))

    def test_points_outside_raise_or_give_nan(self):
        far = [[1.0, 0.0, 0.0]]  # 1 m: far outside the meshed domain
        with self.assertRaises(ValueError):
            self.sol.B(far)
        self.assertTrue(np.isnan(self.sol.B(far, outside="nan")).all())
        with self.assertRaises(ValueError):
            self.sol.B([[0.0, 0.0, 0.0]], unit="inch")

    def test_write_is_the_command_line_output(self):
        with tempfile.TemporaryDirectory() as out:
            files = self.sol.write(out)
            cli_files = [f for f in os.listdir(self.tmp.name) if not f.startswith(".")]
            self.assertEqual(sorted(files), sorted(cli_files))
            with open(os.path.join(out, "forces.csv"), encoding="utf-8") as a, \
                    open(os.path.join(self.tmp.name, "forces.csv"), encoding="utf-8") as b:
                self.assertEqual(a.read(), b.read())


class Axisymmetric(AgainstCommandLine, unittest.TestCase):
    case = "axi/solenoid.yaml"  # a coil: flux linkage and L

    def test_coils_are_the_command_lines(self):
        coils = self.sol.coils
        for c in self.cli["coils"]:
            self.assertEqual(coils[c["name"]]["flux_linkage_Wb"], c["flux_linkage_Wb"])
            self.assertEqual(coils[c["name"]]["inductance_H"], c["inductance_H"])
        np.testing.assert_array_equal(self.sol.inductance_H, self.cli["inductance_H"]["matrix"])

    def test_B_at_points_is_the_probe_field(self):
        for probe in ("bore", "arc30"):
            p = self.sol.probes[probe]
            pts = np.column_stack([p["r"], np.zeros_like(p["r"]), p["z"]])
            self.assert_B_at_probe_points(probe, pts, ["Br", None, "Bz"])

    def test_field_is_symmetric_about_the_axis(self):
        p = self.sol.probes["bore"]
        phi = np.deg2rad(40.0)
        pts = np.column_stack([p["r"] * np.cos(phi), p["r"] * np.sin(phi), p["z"]])
        b = self.sol.B(pts, unit="mm")
        np.testing.assert_allclose(b[:, 0], p["Br"] * np.cos(phi), atol=1e-12)
        np.testing.assert_allclose(b[:, 1], p["Br"] * np.sin(phi), atol=1e-12)
        np.testing.assert_allclose(b[:, 2], p["Bz"], atol=1e-12)


class AxisymmetricForce(AgainstCommandLine, unittest.TestCase):
    case = "axi/magnet_over_plate.yaml"  # nonlinear steel, stress contour force
    mesh_scale = 3.0


class Solid(AgainstCommandLine, unittest.TestCase):
    case = "3d/magnet_and_ball_small.yaml"  # P1, CG + BoomerAMG
    mesh_scale = 1.0

    def test_B_at_points_is_the_probe_field(self):
        for probe in ("r18", "z_axis"):
            p = self.sol.probes[probe]
            pts = np.column_stack([p["x"], p["y"], p["z"]])
            self.assert_B_at_probe_points(probe, pts, ["Bx", "By", "Bz"])

    def test_mm_and_m_give_the_same_field(self):
        pts_mm = np.array([[0.0, 0.0, 12.0], [5.0, -3.0, 1.0]])
        np.testing.assert_array_equal(self.sol.B(pts_mm, unit="mm"), self.sol.B(pts_mm * 1e-3))
        h = self.sol.H(pts_mm, unit="mm")
        # Outside the magnet and the ball B = mu0 H, but H is the element field and B the
        # recovered one: equal within the (coarse) element error, not bit for bit.
        b = self.sol.B(pts_mm[:1], unit="mm")[0]
        self.assertLess(np.linalg.norm(4e-7 * np.pi * h[0] - b), 0.1 * np.linalg.norm(b))

    def test_mesh_arrays(self):
        mesh = self.sol.mesh
        self.assertEqual(mesh.nodes.shape, (self.cli["nodes"], 3))
        self.assertEqual(mesh.elements.shape, (self.cli["elements"], 4))


class Analytic(unittest.TestCase):
    def test_analytic_is_the_command_lines(self):
        case = example("axi/solenoid.yaml")  # closed forms: coil linkage and L, probes
        answer = magfem.analytic(magfem.Case.load(case))
        with tempfile.TemporaryDirectory() as out:
            cli, cli_probes = solve_cli(case, None, out, command="analytic")
        self.assertEqual(but_times(answer.summary), but_times(cli))
        self.assertEqual(answer.summary["coils"], cli["coils"])
        np.testing.assert_array_equal(answer.inductance_H, cli["inductance_H"]["matrix"])
        self.assertEqual(answer.coils["winding"]["flux_linkage_Wb"],
                         cli["coils"][0]["flux_linkage_Wb"])
        for name, columns in cli_probes.items():
            for col, values in columns.items():
                np.testing.assert_allclose(answer.probes[name][col], values, rtol=1e-9,
                                           atol=1e-12, err_msg=name + "." + col)

    def test_unknown_model_names_the_option(self):
        with self.assertRaises(magfem.InputError) as ctx:
            magfem.analytic(magfem.Case.load(example("3d/magnetized_sphere.yaml")), model="x")
        self.assertEqual(ctx.exception.field, "model")


class ExactField(unittest.TestCase):
    """B and H at arbitrary points (not probe points) of the diametric cylinder against its
    exact field (examples/2d/diametric_cylinder.yaml): B_r = 1 T along x, radius 10 mm."""

    @classmethod
    def setUpClass(cls):
        cls.sol = magfem.Case.load(example("2d/diametric_cylinder.yaml")).solve(mesh_scale=2.0)

    def test_inside_and_outside(self):
        rng = np.random.default_rng(7)
        r = np.concatenate([rng.uniform(0, 9, 50), rng.uniform(11, 20, 50)])  # mm
        phi = rng.uniform(0, 2 * np.pi, 100)
        pts = np.column_stack([r * np.cos(phi), r * np.sin(phi), rng.uniform(-5, 5, 100)])
        inside = r < 10
        a2 = (10.0 / np.where(inside, 10.0, r)) ** 2
        br, bphi = 0.5 * a2 * np.cos(phi), 0.5 * a2 * np.sin(phi)
        exact = np.column_stack([br * np.cos(phi) - bphi * np.sin(phi),
                                 br * np.sin(phi) + bphi * np.cos(phi), 0 * r])
        exact[inside] = [0.5, 0.0, 0.0]
        # Element error: 5e-5 T in the magnet, up to ~3e-3 T in the coarse outer air (4 mm
        # triangles at mesh-scale 2); 5e-3 T is 1 % of the field, far below a wrong point or
        # component (0.1 T and more).
        np.testing.assert_allclose(self.sol.B(pts, unit="mm"), exact, atol=5e-3)
        mu0 = 4e-7 * np.pi
        h_exact = exact / mu0
        h_exact[inside] = [-0.5 / mu0, 0.0, 0.0]  # H = (B - B_r) / mu0 in the magnet
        np.testing.assert_allclose(self.sol.H(pts, unit="mm"), h_exact, atol=5e-3 / mu0)


def nonlinear_case(**solver):
    import yaml
    with open(example("axi/magnet_over_plate.yaml"), encoding="utf-8") as f:
        d = yaml.safe_load(f)
    d["solver"].update(solver)
    return magfem.Case.from_dict(d)


class Errors(unittest.TestCase):
    def test_no_convergence_raises_solve_error(self):
        with self.assertRaises(magfem.SolveError) as ctx:
            nonlinear_case(max_iterations=1).solve(mesh_scale=4.0)
        self.assertIn("did not converge", str(ctx.exception))

    def test_bad_arguments_name_the_field(self):
        case = magfem.Case.load(example("axi/solenoid.yaml"))
        for kwargs, field in (({"order": 3}, "order"), ({"mesh_scale": 0}, "mesh_scale"),
                              ({"threads": 0}, "threads")):
            with self.assertRaises(magfem.InputError) as ctx:
                case.solve(**kwargs)
            self.assertEqual(ctx.exception.field, field)

    def test_bad_case_names_the_field(self):
        import yaml
        with open(example("axi/solenoid.yaml"), encoding="utf-8") as f:
            d = yaml.safe_load(f)
        d["regions"][0]["material"] = "unobtainium"
        with self.assertRaises(magfem.InputError) as ctx:
            magfem.Case.from_dict(d).solve()
        self.assertIn("regions[0]", ctx.exception.field)
        self.assertIn("material", ctx.exception.field)


class Interrupts(unittest.TestCase):
    def test_progress_sees_the_stages(self):
        seen = []
        magfem.Case.load(example("axi/solenoid.yaml")).solve(
            mesh_scale=4.0, threads=1, progress=lambda kind, text: seen.append((kind, text)))
        stages = [t for k, t in seen if k == "stage"]
        self.assertEqual(stages[0], "meshing")
        self.assertEqual(stages[-1], "post-processing")

    def test_ctrl_c_raises_keyboard_interrupt_and_stops_the_solve(self):
        # The last text of each kind of report. A C-level callable on purpose: it runs no
        # Python bytecode, so the interpreter never looks at signals inside it and only the
        # solve's own check can raise (a Python callback would raise from its first line).
        last = {}
        case = nonlinear_case()
        # A real SIGINT, as the terminal sends, from another thread 50 ms into the solve
        # (~0.5 s): it arrives while the solve runs in C++ without the GIL.
        threading.Timer(0.05, os.kill, (os.getpid(), signal.SIGINT)).start()
        with self.assertRaises(KeyboardInterrupt):
            case.solve(mesh_scale=3.0, progress=last.__setitem__)
        self.assertNotEqual(last.get("stage"), "post-processing")  # stopped early

    def test_exception_in_progress_ends_the_solve(self):
        def fail(kind, text):
            if text.startswith("assembly"):
                raise KeyError("from the callback")

        with self.assertRaises(KeyError):
            magfem.Case.load(example("axi/solenoid.yaml")).solve(mesh_scale=4.0, progress=fail)

    def test_exception_in_a_krylov_report_waits_for_the_next_stage(self):
        # CG + BoomerAMG: the iteration reports come from PETSc's monitor, where nothing may
        # be thrown; the exception is kept and raised at the next stage.
        seen = []

        def fail_in_iteration(kind, text):
            seen.append(kind)
            if kind == "iteration":
                raise KeyError("from inside PETSc")

        with self.assertRaises(KeyError):
            magfem.Case.load(example("3d/magnet_and_ball_small.yaml")).solve(
                progress=fail_in_iteration)
        self.assertEqual(seen.count("iteration"), 1)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
